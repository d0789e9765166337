#include "checks/rays_per_sample.h"

#include <cstdio>

namespace pathlab::grader {

namespace {

std::string figures(const char* what, double student, double reference) {
    char text[160];
    std::snprintf(text, sizeof text, "%.2f %s per sample against the reference's %.2f", student,
                  what, reference);
    return text;
}

/// The step of each lab that decides how many bounce rays a sample traces.
std::string bounceSpecification(Lab lab) {
    switch (lab) {
    case Lab::Branching:
        return "lab 1 traces a component's ray only where that component is not black "
               "(TODO lab1.3 to lab1.5)";
    case Lab::Uniform:
        return "lab 2 picks among all three components, black ones included: probability 1/3 "
               "each, and traces no ray when the picked component is black (TODO lab2.3, lab2.4)";
    case Lab::Importance:
        return "lab 3 traces one ray per hit, the component picked with a probability "
               "proportional to its strength, and none from a near-black surface (TODO lab3.3, "
               "lab3.4)";
    case Lab::Roulette:
        return "lab 4 continues a path with probability ctx.continueProb at every hit "
               "(TODO lab4.2)";
    case Lab::Glossy:
        return "lab 5 continues a path with probability ctx.continueProb at every hit, as lab 4 "
               "does, with one ray of the picked component (TODO lab5.3, lab5.4)";
    case Lab::Mis:
        return "lab 6 continues a path with probability ctx.continueProb at every hit, as lab 5 "
               "does, with one ray of the picked component; its light sample at a glossy "
               "surface is a shadow ray (TODO lab6.3 to lab6.5)";
    default:
        // A lab added to the lab list since these words were written: the reference solution's
        // count is its specification until it has words of its own here.
        return "lab " + std::to_string(labNumber(lab)) +
               "'s steps decide how many bounce rays a sample traces, as the reference "
               "solution traces them";
    }
}

} // namespace

RaysPerSample raysPerSample(const RayCounters& rays, double samples) {
    if (!(samples > 0)) return {};
    const double traced = static_cast<double>(rays.intersect) / samples;
    return {1.0, traced > 1 ? traced - 1 : 0.0, static_cast<double>(rays.occluded) / samples};
}

std::string raysText(const RaysPerSample& rays) {
    char text[96];
    std::snprintf(text, sizeof text, "%.0f camera + %.2f bounce + %.2f shadow", rays.camera,
                  rays.bounce, rays.shadow);
    return text;
}

std::string specificationDeparture(Lab lab, const RaysPerSample& student,
                                   const RaysPerSample& reference) {
    // Margins far above the runs' sampling noise (a few parts in 1000 at the grader's sizes):
    // only a different estimator moves these figures this much.
    if (student.shadowPerTrace() > 1.25 * reference.shadowPerTrace() + 0.01)
        return "next-event estimation runs more than once per hit: " +
               figures("shadow rays per traced ray", student.shadowPerTrace(),
                       reference.shadowPerTrace()) +
               "; the lab calls ctx.directLight(hit) once at each hit (given in the lab file)";
    if (student.bounce > 1.15 * reference.bounce + 0.02)
        return bounceSpecification(lab) +
               "; yours traces more: " + figures("bounce rays", student.bounce, reference.bounce);
    if (!isDepthLimited(lab) && student.bounce < 0.85 * reference.bounce - 0.02)
        return bounceSpecification(lab) +
               "; yours ends paths sooner (a constant in place of ctx.continueProb?): " +
               figures("bounce rays", student.bounce, reference.bounce);
    return "";
}

} // namespace pathlab::grader
