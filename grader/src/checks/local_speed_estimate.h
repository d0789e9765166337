#pragma once
/// Speed in the student's own `make grade`, where the reference solutions are not there to time
/// against: the student's timed runs against the solutions' stored figures (lab_figures.json).
/// Rays per sample by kind do not depend on the machine and compare as they are; samples per
/// CPU-second do, and are carried to this machine by the kit's own cost of a ray measured on both
/// (kit_ray_cost.h). The estimate only warns: the instructor's grader times both on one machine.

#include "checks/rays_per_sample.h"
#include "checks/rubric.h"
#include "common/by_lab.h"

#include <string>
#include <vector>

namespace pathlab::grader {

/// The reference solutions' timed runs as stored with the kit, and the kit's cost of a ray on
/// the machine they were measured on.
struct StoredSolutionSpeed {
    ByLab<double> samplesPerCpuSecond; ///< 0 where not stored
    ByLab<RaysPerSample> rays;
    bool raysKnown = false;
    double kitCpuSecondsPerRay = 0; ///< 0: not stored
};

struct LocalSpeedEstimate {
    /// Your samples per CPU-second over the reference's as it would run on this machine; 0:
    /// unknown (nothing stored).
    double ratio = 0;
    /// Whether `ratio` carries the reference's figure here by the kit's cost of a ray (true), or
    /// rests on rays per sample alone, as if a ray cost the same in both (false).
    bool scaledByRayCost = false;
    double raysRatio = 0;       ///< your rays per sample ÷ the reference's (all kinds); 0: unknown
    double workPerRayRatio = 0; ///< your CPU time per ray ÷ the reference's here; 0: unknown
    /// Why yours is slower, each in a sentence ending in its likely cause as a question.
    std::vector<std::string> causes;
    /// Below the rubric's threshold with a cause named: the instructor's grader would likely
    /// fail the speed check.
    bool atRisk = false;
};

/// Above this multiple of the reference's CPU time per ray, a lab is said to do work besides its
/// rays: far outside what two machines' differences in the kit's cost of a ray leave.
constexpr double ExtraWorkPerRay = 1.5;

/// The estimate for `lab` from your timed runs (`samplesPerCpuSecond`, `rays`), the stored
/// figures, and the kit's cost of a ray here (0: not measured).
LocalSpeedEstimate estimateSpeedLocally(const Rubric& rubric, Lab lab, double samplesPerCpuSecond,
                                        const RaysPerSample& rays,
                                        const StoredSolutionSpeed& stored,
                                        double kitCpuSecondsPerRayHere);

} // namespace pathlab::grader
