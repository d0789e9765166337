#include "diagnosis/diagnosis.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace pathlab::grader {

namespace {

/// Σ over path vertices of the expected weight of the paths that reach them, times what they
/// add there: Le if the ray that arrived may add emission, and next-event estimation's a·Le.
double furnaceValue(Lab lab, const FurnaceModel& m, const FurnaceBehaviour& b) {
    const double a = m.walls == FurnaceWalls::Diffuse ? m.reflectance : 0;
    const double s = m.walls == FurnaceWalls::Mirror ? m.reflectance : 0;
    // A branch that divides by continueProb k times weighs a continued path by q^(1-k).
    const auto roulette = [&](int divisions) {
        return !isDepthLimited(lab) ? std::pow(m.continueProb, 1 - divisions) : 1.0;
    };
    const double diffuseRoulette = roulette(b.rouletteDivisionsDiffuse);
    const double specularRoulette = roulette(b.rouletteDivisionsSpecular);
    const int limit = b.fixedDepth >= 0 ? b.fixedDepth : m.maxDepth;
    const int lastDepth = isDepthLimited(lab) || b.depthLimitKept ? limit + b.depthShift : 100000;
    // The expected weight of the paths that reach depth d by a camera, diffuse or specular ray.
    double camera = 1, diffuse = 0, specular = 0, value = 0;
    for (int d = 0; d <= lastDepth; ++d) {
        const double reaching = camera + diffuse + specular;
        if (reaching < 1e-12) break;
        if (reaching > 1e6) return INFINITY;
        value += camera + (b.emissionAfterDiffuse ? diffuse : 0) +
                 (b.emissionAfterSpecular ? specular : 0) + reaching * b.directWeight * a;
        camera = 0;
        diffuse = reaching * diffuseRoulette * b.diffuseWeight * a;
        specular = reaching * specularRoulette * b.mirrorWeight * s;
    }
    return value * m.emission;
}

struct Candidate {
    std::string cause;
    FurnaceBehaviour behaviour;
};

/// The known bugs of this lab (diagnosis_table.h), each with the behaviour that gives its
/// furnace values; `depths`: the maxDepths the furnaces were rendered at.
std::vector<Candidate> candidates(Lab lab, const std::vector<int>& depths, bool stepsOpen) {
    std::vector<Candidate> list;
    for (const KnownBug& bug : knownBugs()) {
        if (!(bug.labs & labBit(lab)) || !bug.fits(stepsOpen)) continue;
        FurnaceBehaviour b;
        bug.behave(b);
        if (!bug.perObservedDepth) {
            list.push_back({bugSentence(bug, lab), b});
            continue;
        }
        // Only furnaces at two maxDepths tell a lab that renders at one of them regardless.
        if (depths.size() < 2) continue;
        for (int depth : depths) {
            b.fixedDepth = depth;
            list.push_back({bugSentence(bug, lab, depth), b});
        }
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
    return furnaceValue(lab, model, FurnaceBehaviour{});
}

std::string furnaceFormula(Lab lab, const FurnaceModel& m) {
    // Diffuse walls: the camera ray's Le, then a·Le of next-event estimation at each of the
    // D + 1 vertices. Mirror walls: Le at each vertex, seen through the mirror bounces.
    const bool diffuse = m.walls == FurnaceWalls::Diffuse;
    const char* k = diffuse ? "a" : "s";
    char text[160];
    if (isDepthLimited(lab))
        std::snprintf(text, sizeof text,
                      "Le*(1 - %s^(D+%d))/(1 - %s) with Le = %g, %s = %g, D = %d", k,
                      diffuse ? 2 : 1, k, m.emission, k, m.reflectance, m.maxDepth);
    else
        std::snprintf(text, sizeof text, "Le/(1 - %s) with Le = %g, %s = %g", k, m.emission, k,
                      m.reflectance);
    return text;
}

std::vector<std::string>
likelyFurnaceCauses(Lab lab, const std::vector<FurnaceObservation>& observations, bool stepsOpen) {
    std::vector<std::pair<double, std::string>> matches; // (misfit, cause)
    std::vector<int> depths;
    for (const FurnaceObservation& o : observations)
        if (std::find(depths.begin(), depths.end(), o.model.maxDepth) == depths.end())
            depths.push_back(o.model.maxDepth);
    for (const Candidate& c : candidates(lab, depths, stepsOpen)) {
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
    for (auto& match : matches) causes.push_back(std::move(match.second));
    return causes;
}

std::string likelyNonfiniteCause(Lab lab) { return hintFor(HintTopic::NonfiniteRadiance, lab); }

std::string likelyDirectionCause(Lab lab) { return hintFor(HintTopic::DiffuseDirection, lab); }

std::string likelyRefractionCause(Lab lab) { return hintFor(HintTopic::Refraction, lab); }

bool channelsOffOppositeWays(const std::vector<ChannelInterval>& channels) {
    const bool tooBright = std::any_of(channels.begin(), channels.end(),
                                       [](const ChannelInterval& c) { return c.low > 1; });
    const bool tooDark = std::any_of(channels.begin(), channels.end(),
                                     [](const ChannelInterval& c) { return c.high < 1; });
    return tooBright && tooDark;
}

std::string likelyPickDivideCause(Lab lab) { return hintFor(HintTopic::PickDivideMismatch, lab); }

double furnaceValueWithBug(Lab lab, const FurnaceModel& model, const KnownBug& bug, int depth) {
    FurnaceBehaviour b;
    bug.behave(b);
    if (bug.perObservedDepth) b.fixedDepth = depth;
    return furnaceValue(lab, model, b);
}

} // namespace pathlab::grader
