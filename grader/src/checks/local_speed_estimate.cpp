#include "checks/local_speed_estimate.h"

#include <cstdio>

namespace pathlab::grader {

namespace {

double total(const RaysPerSample& r) { return r.camera + r.bounce + r.shadow; }

/// The likeliest reason a lab of this kind traces more bounce rays than its estimator.
const char* extraBounceCause(Lab lab) {
    switch (lab) {
    case Lab::Branching:
    case Lab::Uniform: return "a black component traced?";
    case Lab::Importance: return "more than one ray per hit, or rays from near-black surfaces?";
    case Lab::Roulette: return "paths continued without ctx.continueProb's roulette?";
    case Lab::Glossy:
        return "paths continued without ctx.continueProb's roulette, or a glossy "
               "ray traced below the surface?";
    case Lab::Mis:
        return "paths continued without ctx.continueProb's roulette, a glossy ray traced below "
               "the surface, or the glossy bounce's first hit traced twice?";
    default: return "rays its steps do not ask for?"; // a lab added since: no cause of its own
    }
}

std::string times(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2g×", x);
    return text;
}

std::string perSample(double yours, double reference) {
    char text[96];
    std::snprintf(text, sizeof text, " (%.2f per sample against %.2f)", yours, reference);
    return text;
}

/// The rays in which `yours` departs from `reference` enough to cost speed, in words.
std::vector<std::string> rayCauses(Lab lab, const RaysPerSample& yours,
                                   const RaysPerSample& reference) {
    // The margins of specificationDeparture (rays_per_sample.cpp): far above the runs' noise.
    std::vector<std::string> causes;
    if (yours.bounce > 1.15 * reference.bounce + 0.02)
        causes.push_back("traces " + times(yours.bounce / reference.bounce) +
                         " the bounce rays of the lab's estimator" +
                         perSample(yours.bounce, reference.bounce) + ": " + extraBounceCause(lab));
    if (yours.shadowPerTrace() > 1.25 * reference.shadowPerTrace() + 0.01)
        causes.push_back("traces " + times(yours.shadowPerTrace() / reference.shadowPerTrace()) +
                         " the shadow rays per hit of the lab's estimator" +
                         perSample(yours.shadow, reference.shadow) +
                         ": ctx.directLight(hit) called more than once per hit?");
    return causes;
}

} // namespace

LocalSpeedEstimate estimateSpeedLocally(const Rubric& rubric, Lab lab, double samplesPerCpuSecond,
                                        const RaysPerSample& rays,
                                        const StoredSolutionSpeed& stored,
                                        double kitCpuSecondsPerRayHere) {
    LocalSpeedEstimate e;
    const double storedRate = stored.samplesPerCpuSecond[lab];
    if (!stored.raysKnown || !(total(stored.rays[lab]) > 0) || !(total(rays) > 0)) return e;
    e.raysRatio = total(rays) / total(stored.rays[lab]);
    e.causes = rayCauses(lab, rays, stored.rays[lab]);
    if (storedRate > 0 && samplesPerCpuSecond > 0 && stored.kitCpuSecondsPerRay > 0 &&
        kitCpuSecondsPerRayHere > 0) {
        // The reference's samples per CPU-second as this machine would give them: its rays
        // cost here what the kit's own cost here, in the same proportion as there.
        const double referenceHere =
            storedRate * stored.kitCpuSecondsPerRay / kitCpuSecondsPerRayHere;
        e.ratio = samplesPerCpuSecond / referenceHere;
        e.scaledByRayCost = true;
        e.workPerRayRatio = 1 / (e.ratio * e.raysRatio);
        if (e.workPerRayRatio > ExtraWorkPerRay)
            e.causes.push_back("spends " + times(e.workPerRayRatio) +
                               " the reference's CPU time per ray (carried to this machine by "
                               "the kit's own cost of a ray): work repeated per sample, or "
                               "memory allocated per sample?");
    } else {
        e.ratio = 1 / e.raysRatio; // as if each ray cost what the reference's do
    }
    e.atRisk = e.ratio < rubric.minSpeedRatio && !e.causes.empty();
    return e;
}

} // namespace pathlab::grader
