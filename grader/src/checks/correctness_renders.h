#pragma once
/// The render the correctness check makes of one scene's seeds: also the speed check's timed
/// run, argument for argument, so that nothing a lab can read (its command line, its scene, its
/// image size, seeds and threads) tells it that it is being timed.

#include "checks/grader_setup.h"

namespace pathlab::grader {

/// The seed base of the correctness check's first attempt (a retry takes fresh seeds).
inline uint64_t firstSeedBase(const GraderSetup& setup) { return setup.seedBase * 1000; }

/// The render of `scene`'s rubric seeds from `seedBase` for `lab`, with `runner`'s labs.
RenderRequest correctnessRequest(const GraderSetup& setup, const GradingScene& scene, Lab lab,
                                 uint64_t seedBase, const LabRunner& runner);

/// The grading scene the rubric times on (speed.scene, one of its public scenes); nullptr if
/// the setup has none of that name.
const GradingScene* speedScene(const GraderSetup& setup);

} // namespace pathlab::grader
