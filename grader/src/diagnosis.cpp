#include "diagnosis.h"

#include <cmath>
#include <vector>

namespace pathlab::grader {

namespace {

/// How a (possibly wrong) lab behaves in the furnace, in the few numbers that decide its value.
struct Behaviour {
    double bounceWeight = 1;        ///< the continued path's weight relative to Kd (correct: 1)
    double directWeight = 1;        ///< next-event estimation's weight (correct: 1; none: 0)
    bool emissionAfterDiffuse = false;
    int depthShift = 0;             ///< labs 1-3: bounces beyond (or short of) maxDepth
    bool rouletteWeightMissing = false;
    bool rouletteWeightTwice = false;
};

/// Σ over path vertices d of (weight·a)^d · (emission at d + direct light at d).
double furnaceValue(Lab lab, const FurnaceModel& m, const Behaviour& b) {
    const double a = m.albedo;
    double perBounce = b.bounceWeight * a;
    if (lab == Lab::Roulette && b.rouletteWeightMissing) perBounce *= m.continueProb;
    if (lab == Lab::Roulette && b.rouletteWeightTwice) perBounce /= m.continueProb;
    const int lastDepth = isDepthLimited(lab) ? m.maxDepth + b.depthShift : 100000;
    double value = 0, weight = 1;
    for (int d = 0; d <= lastDepth && weight > 1e-12; ++d) {
        const double emission = (d == 0 || b.emissionAfterDiffuse) ? 1.0 : 0.0;
        value += weight * (emission + b.directWeight * a);
        weight *= perBounce;
        if (weight > 1e6) return INFINITY;
    }
    return value;
}

struct Candidate {
    const char* cause;
    Behaviour behaviour;
    bool applies(Lab lab) const { return lab == only || only == AnyLab; }
    static constexpr Lab AnyLab = static_cast<Lab>(-1);
    Lab only = AnyLab;
};

std::vector<Candidate> candidates() {
    const double pi = 3.14159265358979;
    std::vector<Candidate> list;
    auto add = [&](const char* cause, Behaviour b, Lab only = Candidate::AnyLab) {
        list.push_back({cause, b, only});
    };
    add("no bounce rays yet: the lab renders direct light only (its TODOs are still open)",
        {0, 1, false, 0, false});
    add("emission counted twice: it is added after diffuse bounces too, although next-event "
        "estimation already counted it (handout TODO lab1.1)", {1, 1, true, 0, false});
    add("no next-event estimation: ctx.directLight(hit) is missing", {1, 0, false, 0, false});
    add("no next-event estimation, with emission added after every bounce instead",
        {1, 0, true, 0, false});
    add("a factor of pi: the diffuse bounce is weighted by pi*Kd; with cosine sampling the weight "
        "is Kd alone (handout TODO lab1.3)", {pi, 1, false, 0, false});
    add("a factor of 1/pi: the diffuse bounce is weighted by Kd/pi; with cosine sampling the "
        "weight is Kd alone (handout TODO lab1.3)", {1 / pi, 1, false, 0, false});
    add("direct light weighted by an extra pi", {1, pi, false, 0, false});
    for (Lab lab : {Lab::Branching, Lab::Uniform, Lab::Importance}) {
        add("depth off by one: one bounce too many (the test should be depth < maxDepth, with "
            "the primary hit at depth 0; TODO lab1.2)", {1, 1, false, 1, false}, lab);
        add("depth off by one: one bounce too few (the primary hit is depth 0; TODO lab1.2)",
            {1, 1, false, -1, false}, lab);
    }
    add("forgot to divide by the pick probability 1/3 (TODO lab2.4)", {1.0 / 3, 1, false, 0, false},
        Lab::Uniform);
    add("divided by the pick probability twice", {3, 1, false, 0, false}, Lab::Uniform);
    add("divided by 1/3 instead of the chosen component's probability (TODO lab3.4)",
        {3, 1, false, 0, false}, Lab::Importance);
    add("Russian-roulette weight missing: a continued path must be divided by continueProb "
        "(TODO lab4.4)", {1, 1, false, 0, true}, Lab::Roulette);
    add("divided by continueProb twice", {1, 1, false, 0, false, true}, Lab::Roulette);
    return list;
}

} // namespace

double correctFurnaceValue(Lab lab, const FurnaceModel& model) {
    return furnaceValue(lab, model, Behaviour{});
}

std::string diagnoseFurnace(Lab lab, const FurnaceModel& model, double observed,
                            double standardError) {
    std::string best;
    double bestDistance = INFINITY;
    for (const Candidate& c : candidates()) {
        if (!c.applies(lab)) continue;
        const double predicted = furnaceValue(lab, model, c.behaviour);
        if (!std::isfinite(predicted)) {
            if (!std::isfinite(observed) || observed > 20 * correctFurnaceValue(lab, model)) return c.cause;
            continue;
        }
        // Close: within 4 standard errors, or 1.5% when the run is very precise.
        const double distance = std::fabs(observed - predicted);
        const double tolerance = std::max(4 * standardError, 0.015 * predicted);
        if (distance < tolerance && distance < bestDistance) {
            best = c.cause;
            bestDistance = distance;
        }
    }
    return best;
}

} // namespace pathlab::grader
