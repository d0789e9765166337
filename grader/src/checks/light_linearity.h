#pragma once
/// Whether a lab is linear in the light it finds: every estimator of the labs is, however noisy a
/// sample, and a clamp, a cap or a min/max on radiance (a "firefly clamp") is not, and biased.
/// The check renders a public scene again, from the same seeds, with every light at 1/64 of its
/// strength: a power of two, so that a linear lab's every sample, and so its images' means, come
/// out exactly 1/64 of the full-light ones, float rounding included. Any other difference is the
/// lab's own doing. The furnaces' models of known bugs (diagnosis.h) assume a linear lab: for one
/// that is not, this is the cause to tell.

#include "checks/grader_setup.h"

#include <string>
#include <vector>

namespace pathlab::grader {

/// The factor every light of the scene is scaled by: 2^-6.
constexpr double DimmedLight = 1.0 / 64;

/// What the dimmed render showed.
struct LinearityFinding {
    bool measured = false; ///< false when the dimmed renders failed (nothing to say)
    bool linear = true;
    /// For a lab that is not linear, the sentence for the student: both lights' observed /
    /// expected and the likely cause.
    std::string cause;
};

/// Renders `scene` (a public one) with its lights at DimmedLight from `seedBase`'s seeds and
/// compares its region means times 64 with `fullLight`, the region means (flat [region][channel],
/// over the seeds) the lab rendered of the scene itself from the same seeds; `expected` is the
/// scene's reference for `lab`.
LinearityFinding checkLightLinearity(const GraderSetup& setup, Lab lab, const GradingScene& scene,
                                     uint64_t seedBase, const std::vector<double>& fullLight,
                                     const Expectation& expected);

/// Whether means of a render at full light and of the same render with every light at
/// DimmedLight (the same layout, any number of values) agree as a linear lab's do: each dimmed
/// mean times 64 equal to the full one, up to far less than any clamp changes.
bool scalesWithLight(const std::vector<double>& fullLight, const std::vector<double>& dimmedLight);

/// The sentence for a lab that is not linear, from whole-image observed/expected per channel at
/// full light and with the lights dimmed (each [red, green, blue]).
std::string nonLinearCause(const std::string& scene, const std::vector<double>& fullRatio,
                           const std::vector<double>& dimmedRatio);

} // namespace pathlab::grader
