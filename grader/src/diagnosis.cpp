#include "diagnosis.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <utility>

namespace pathlab::grader {

namespace {

/// The handouts' step for each part of a lab, indexed by Lab (0: that lab has no such step).
/// Labs 2-4 trace the picked component and weigh it in one step (lab 4 divides by both of its
/// probabilities in step 4.4); lab 4 has no depth limit.
using StepTable = int[4];
constexpr StepTable EmissionStep = {1, 1, 1, 1};
constexpr StepTable DepthLimitStep = {2, 2, 2, 0};
constexpr StepTable FirstBounceStep = {3, 3, 3, 2};
constexpr StepTable DiffuseWeightStep = {3, 4, 4, 4};
constexpr StepTable RefractionStep = {5, 4, 4, 3};
constexpr StepTable ProbabilityDivisionStep = {0, 4, 4, 4};
constexpr StepTable NearBlackStopStep = {0, 0, 3, 3};

/// "TODO lab3.1": the lab's step in `steps`, as the lab file and its handout name it.
std::string todo(Lab lab, const StepTable& steps) {
    return "TODO lab" + std::to_string(static_cast<int>(lab) + 1) + "." +
           std::to_string(steps[static_cast<int>(lab)]);
}

/// A cause for the student, ending with the lab's step it is about.
std::string withStep(const std::string& cause, Lab lab, const StepTable& step) {
    return cause + " (" + todo(lab, step) + ")";
}

/// How a (possibly wrong) lab behaves in a furnace, in the few numbers that decide its value.
struct Behaviour {
    double diffuseWeight = 1; ///< a diffuse bounce's weight relative to Kd, in expectation
    double mirrorWeight = 1;  ///< a mirror bounce's weight relative to Ks, in expectation
    double directWeight = 1;  ///< next-event estimation's weight (none: 0)
    bool emissionAfterDiffuse = false;
    bool emissionAfterSpecular = true;
    int depthShift = 0;        ///< labs 1-3: bounces beyond (or short of) maxDepth
    int fixedDepth = -1;       ///< labs 1-3: a depth limit of its own, whatever maxDepth is (-1: none)
    int rouletteDivisions = 1; ///< lab 4: how often a continued path is divided by continueProb
};

/// Σ over path vertices of the expected weight of the paths that reach them, times what they
/// add there: Le if the ray that arrived may add emission, and next-event estimation's a·Le.
double furnaceValue(Lab lab, const FurnaceModel& m, const Behaviour& b) {
    const double a = m.walls == FurnaceWalls::Diffuse ? m.reflectance : 0;
    const double s = m.walls == FurnaceWalls::Mirror ? m.reflectance : 0;
    const double roulette =
        lab == Lab::Roulette ? std::pow(m.continueProb, 1 - b.rouletteDivisions) : 1;
    const int limit = b.fixedDepth >= 0 ? b.fixedDepth : m.maxDepth;
    const int lastDepth = isDepthLimited(lab) ? limit + b.depthShift : 100000;
    // The expected weight of the paths that reach depth d by a camera, diffuse or specular ray.
    double camera = 1, diffuse = 0, specular = 0, value = 0;
    for (int d = 0; d <= lastDepth; ++d) {
        const double reaching = camera + diffuse + specular;
        if (reaching < 1e-12) break;
        if (reaching > 1e6) return INFINITY;
        value += camera + (b.emissionAfterDiffuse ? diffuse : 0) +
                 (b.emissionAfterSpecular ? specular : 0) + reaching * b.directWeight * a;
        camera = 0;
        diffuse = reaching * roulette * b.diffuseWeight * a;
        specular = reaching * roulette * b.mirrorWeight * s;
    }
    return value;
}

struct Candidate {
    std::string cause;
    Behaviour behaviour;
};

/// The known bugs of this lab, each with the behaviour that gives its furnace values;
/// `depths`: the maxDepths the furnaces were rendered at.
std::vector<Candidate> candidates(Lab lab, const std::vector<int>& depths) {
    const double pi = 3.14159265358979;
    std::vector<Candidate> list;
    // A cause ends with the lab's step it is about, where the lab has one.
    auto add = [&](const std::string& cause, const StepTable* step,
                   const std::function<void(Behaviour&)>& change) {
        Behaviour b;
        change(b);
        list.push_back({step ? withStep(cause, lab, *step) : cause, b});
    };
    const std::string firstBounce = todo(lab, FirstBounceStep);
    add("no bounce rays yet: the lab renders direct light only (its steps from " + firstBounce +
            " on are still open)",
        nullptr, [](Behaviour& b) { b.diffuseWeight = b.mirrorWeight = 0; });
    add("emission after a specular bounce missing: a ray that left a mirror or a refraction "
        "(RayKind::Specular) must add hit.emitted, since next-event estimation never finds a "
        "light in one exact direction",
        &EmissionStep, [](Behaviour& b) { b.emissionAfterSpecular = false; });
    add("emission counted twice: it is added after diffuse bounces too, although next-event "
        "estimation already counted it",
        &EmissionStep, [](Behaviour& b) { b.emissionAfterDiffuse = true; });
    add("no next-event estimation: ctx.directLight(hit), given in the lab file, is missing",
        nullptr, [](Behaviour& b) { b.directWeight = 0; });
    add("no next-event estimation, with emission added after every bounce instead: emission "
        "belongs after camera and specular rays only, beside ctx.directLight(hit)",
        &EmissionStep, [](Behaviour& b) { b.directWeight = 0, b.emissionAfterDiffuse = true; });
    add("a factor of pi: the diffuse bounce is weighted by pi*Kd; with cosine sampling the weight "
        "is Kd alone",
        &DiffuseWeightStep, [&](Behaviour& b) { b.diffuseWeight = pi; });
    add("a factor of 1/pi: the diffuse bounce is weighted by Kd/pi; with cosine sampling the "
        "weight is Kd alone",
        &DiffuseWeightStep, [&](Behaviour& b) { b.diffuseWeight = 1 / pi; });
    add("direct light weighted by an extra pi", nullptr,
        [&](Behaviour& b) { b.directWeight = pi; });
    if (isDepthLimited(lab)) {
        add("depth off by one: one bounce too many: return before the bounce when depth >= "
            "ctx.maxDepth (the primary hit is depth 0)",
            &DepthLimitStep, [](Behaviour& b) { b.depthShift = 1; });
        add("depth off by one: one bounce too few: the primary hit is depth 0", &DepthLimitStep,
            [](Behaviour& b) { b.depthShift = -1; });
        // Furnaces at two maxDepths tell a lab that ignores it: it renders one of them right.
        if (depths.size() >= 2)
            for (int depth : depths)
                add("ctx.maxDepth ignored: the lab renders as if maxDepth were " +
                        std::to_string(depth) + ", whatever ctx.maxDepth says (a constant in its "
                        "place?)",
                    &DepthLimitStep, [depth](Behaviour& b) { b.fixedDepth = depth; });
    }
    // A wrong pick weight scales whichever component is picked.
    auto pickWeight = [](double w) {
        return [w](Behaviour& b) { b.diffuseWeight = b.mirrorWeight = w; };
    };
    if (lab == Lab::Uniform) {
        add("forgot to divide by the pick probability 1/3", &ProbabilityDivisionStep,
            pickWeight(1.0 / 3));
        add("divided by the pick probability twice", &ProbabilityDivisionStep, pickWeight(3));
    }
    if (lab == Lab::Importance)
        add("divided by 1/3 instead of the chosen component's probability",
            &ProbabilityDivisionStep, pickWeight(3));
    if (lab == Lab::Roulette) {
        add("Russian-roulette weight missing: a continued path must be divided by continueProb",
            &ProbabilityDivisionStep, [](Behaviour& b) { b.rouletteDivisions = 0; });
        add("divided by continueProb twice", &ProbabilityDivisionStep,
            [](Behaviour& b) { b.rouletteDivisions = 2; });
    }
    return list;
}

} // namespace

std::optional<FurnaceModel> furnaceModel(const std::string& scene, int maxDepth,
                                         double continueProb) {
    // As models/generate_models.py writes them.
    struct Known {
        const char* scene;
        FurnaceWalls walls;
        double reflectance;
    };
    static const Known known[] = {{"furnace", FurnaceWalls::Diffuse, 0.5},
                                  {"furnace_a08", FurnaceWalls::Diffuse, 0.8},
                                  {"mirror_furnace", FurnaceWalls::Mirror, 0.5}};
    for (const Known& k : known)
        if (scene == k.scene) return FurnaceModel{k.walls, k.reflectance, maxDepth, continueProb};
    return std::nullopt;
}

double correctFurnaceValue(Lab lab, const FurnaceModel& model) {
    return furnaceValue(lab, model, Behaviour{});
}

std::string furnaceFormula(Lab lab, const FurnaceModel& m) {
    // Diffuse walls: the camera ray's Le, then a·Le of next-event estimation at each of the
    // D + 1 vertices. Mirror walls: Le at each vertex, seen through the mirror bounces.
    const bool diffuse = m.walls == FurnaceWalls::Diffuse;
    const char* k = diffuse ? "a" : "s";
    char text[160];
    if (isDepthLimited(lab))
        std::snprintf(text, sizeof text, "Le*(1 - %s^(D+%d))/(1 - %s) with Le = 1, %s = %g, D = %d",
                      k, diffuse ? 2 : 1, k, k, m.reflectance, m.maxDepth);
    else
        std::snprintf(text, sizeof text, "Le/(1 - %s) with Le = 1, %s = %g", k, k, m.reflectance);
    return text;
}

std::vector<std::string> likelyFurnaceCauses(Lab lab,
                                             const std::vector<FurnaceObservation>& observations) {
    std::vector<std::pair<double, std::string>> matches; // (misfit, cause)
    std::vector<int> depths;
    for (const FurnaceObservation& o : observations)
        if (std::find(depths.begin(), depths.end(), o.model.maxDepth) == depths.end())
            depths.push_back(o.model.maxDepth);
    for (const Candidate& c : candidates(lab, depths)) {
        bool explainsAll = true, tellsApart = false;
        double misfit = 0;
        for (const FurnaceObservation& o : observations) {
            const double predicted = furnaceValue(lab, o.model, c.behaviour);
            const double correct = correctFurnaceValue(lab, o.model);
            tellsApart = tellsApart || std::fabs(predicted - correct) > 1e-9 * correct;
            if (!std::isfinite(predicted)) {
                // A series that diverges: any huge or non-finite value fits it.
                explainsAll = explainsAll && !(o.observed < 20 * correct);
                continue;
            }
            // Close: within 4 standard errors, or 1.5% when the run is very precise.
            const double distance = std::fabs(o.observed - predicted);
            const double tolerance = std::max(4 * o.standardError, 0.015 * predicted);
            explainsAll = explainsAll && distance < tolerance;
            misfit += distance / tolerance;
        }
        if (explainsAll && tellsApart) matches.emplace_back(misfit, c.cause);
    }
    std::stable_sort(matches.begin(), matches.end(),
                     [](const auto& x, const auto& y) { return x.first < y.first; });
    std::vector<std::string> causes;
    for (auto& match : matches)
        causes.push_back(std::move(match.second));
    return causes;
}

std::string likelyNonfiniteCause(Lab lab) {
    if (NearBlackStopStep[static_cast<int>(lab)] == 0)
        return "a division by zero (0/0 is NaN, x/0 infinite) or a value used before it is set, "
               "in the lab's own arithmetic";
    return withStep("a division by zero: on a surface with no component at all (the light's "
                    "material has only Ke) the strengths sum to 0 and total/strength is 0/0; the "
                    "near-black stop must return before the pick",
                    lab, NearBlackStopStep);
}

std::string likelyDirectionCause(Lab lab) {
    std::string cause =
        "diffuse directions drawn from part of the hemisphere: on surfaces that are part diffuse, "
        "part mirror or glass, lit from one side, the image differs; is a random number used "
        "twice (the pick's u again in diffuseRay's u, or one number for both of its "
        "coordinates), or the direction drawn around a normal that does not face the incoming "
        "ray? diffuseRay(hit, ctx.sampler.get2D()) with a fresh get2D() after the pick";
    return withStep(cause, lab, DiffuseWeightStep);
}

std::string likelyRefractionCause(Lab lab) {
    return withStep("the view through the glass sphere is wrong: the Kt component must trace "
                    "refractionRay(ray, hit), which bends the ray by Ni and turns into a mirror "
                    "ray under total internal reflection",
                    lab, RefractionStep);
}

} // namespace pathlab::grader
