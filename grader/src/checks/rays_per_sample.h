#pragma once
/// What a lab traces for one sample, counted by the framework in the lab's render (--stats
/// rays): the camera ray, bounce rays, shadow rays. Against the reference solution's on the same
/// scene they tell which step of a lab's specification a slow (or quick) lab departs from. They
/// come from the lab's own process, so the grader explains with them and never scores by them
/// alone.

#include "pathlab/render/lab_registry.h"
#include "pathlab/render/ray_counters.h"

#include <string>

namespace pathlab::grader {

struct RaysPerSample {
    double camera = 0; ///< 1: every sample starts with one camera ray
    double bounce = 0; ///< closest-hit rays after the camera ray: diffuse, mirror, refracted
    double shadow = 0; ///< next-event estimation's occlusion rays

    /// Shadow rays per hit found by a closest-hit ray: next-event estimation runs once per hit.
    double shadowPerTrace() const { return camera + bounce > 0 ? shadow / (camera + bounce) : 0; }
};

/// `rays` counted over `samples` samples (width x height x spp). 0s for no samples.
RaysPerSample raysPerSample(const RayCounters& rays, double samples);

/// "1 camera + 0.93 bounce + 1.62 shadow".
std::string raysText(const RaysPerSample& rays);

/// Where `student`'s rays per sample depart from the lab's specification, which `reference`'s
/// follow (both on the same scene with the same parameters): one sentence naming the step and
/// both figures, or "" where they agree.
std::string specificationDeparture(Lab lab, const RaysPerSample& student,
                                   const RaysPerSample& reference);

} // namespace pathlab::grader
