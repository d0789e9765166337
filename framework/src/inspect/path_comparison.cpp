#include "pathlab/inspect/path_comparison.h"

#include "pathlab/inspect/inspection_numbers.h"
#include "pathlab/render/lab_registry.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pathlab {

namespace {

/// Equal to the precision the replay measures weights with (a difference of two float sums).
bool close(float a, float b) {
    return std::abs(a - b) <= 1e-3f * std::max({std::abs(a), std::abs(b), 1e-4f});
}

bool close(const Color& a, const Color& b) {
    return close(a.r, b.r) && close(a.g, b.g) && close(a.b, b.b);
}

bool closeDirection(const Vec3& a, const Vec3& b) {
    return std::abs(a.x - b.x) < 1e-4f && std::abs(a.y - b.y) < 1e-4f &&
           std::abs(a.z - b.z) < 1e-4f;
}

/// Reads one sample of the lab's and of the reference's side by side.
class SampleWalk {
public:
    SampleWalk(const PixelInspection& lab, const PixelInspection& reference, size_t sample)
        : lab_(lab), parameters_(lab.identity.parameters), sample_(sample),
          ours_(lab.samples[sample]), theirs_(reference.samples[sample]) {}

    /// The first difference, if any; `comparable` is cleared when the draws part.
    std::optional<PathDivergence> firstDifference(bool& comparable) {
        if (auto divergence = differentCalls(comparable)) return divergence;
        return differentWeights();
    }

private:
    std::optional<PathDivergence> differentCalls(bool& comparable) {
        int at = -1; // the vertex the lab's path is at
        const size_t calls = std::min(ours_.calls.size(), theirs_.calls.size());
        for (size_t i = 0; i < calls; ++i) {
            const InspectedCall& a = ours_.calls[i];
            const InspectedCall& b = theirs_.calls[i];
            if (a.type != b.type) return differentCall(a, b, at);
            if (a.type == "end" && lab_.usesRoulette && a.drawsBefore.empty() &&
                !b.drawsBefore.empty())
                return endedWithoutRouletteDraw(at);
            if (a.drawsBefore.size() != b.drawsBefore.size()) {
                comparable = false;
                return divergence(at, "draw-order", "",
                                  "at " + vertexName(at) + " your lab drew " +
                                      std::to_string(a.drawsBefore.size()) +
                                      " random number(s) before its next call where the reference "
                                      "draws " +
                                      std::to_string(b.drawsBefore.size()) +
                                      ": it uses them in another order or number, so its paths "
                                      "cannot be compared with the reference's draw by draw");
            }
            if (a.type == "trace") {
                const InspectedVertex& x = ours_.vertices[static_cast<size_t>(a.vertex)];
                const InspectedVertex& y = theirs_.vertices[static_cast<size_t>(b.vertex)];
                if (x.arrivedBy != y.arrivedBy) return differentPick(x, y, at, a);
                if (!closeDirection(x.ray.direction, y.ray.direction))
                    return divergence(at, "ray", "",
                                      "your lab's " + x.arrivedBy + " ray from " + vertexName(at) +
                                          " goes another way than the reference's, although both "
                                          "drew the same random numbers");
            }
            if (a.vertex >= 0) at = a.vertex;
        }
        return std::nullopt;
    }

    std::optional<PathDivergence> differentCall(const InspectedCall& a, const InspectedCall& b,
                                                int at) {
        if (a.type == "light" || b.type == "light")
            return divergence(at, "direct-light", "",
                              a.type == "light"
                                  ? "your lab asked ctx.directLight at " + vertexName(at) +
                                        " where the reference does not"
                                  : "your lab did not add ctx.directLight(hit) at " +
                                        vertexName(b.vertex >= 0 ? b.vertex : at) +
                                        ", as the reference (and the given code) does");
        if (a.type == "end") {
            const auto& y = theirs_.vertices[static_cast<size_t>(b.vertex)];
            return endedEarly(at, y.arrivedBy, a);
        }
        const auto& x = ours_.vertices[static_cast<size_t>(a.vertex)];
        return wentOn(at, x.arrivedBy);
    }

    /// Both ended their paths at `at`: the lab without a random number, the reference after its
    /// roulette draw (which said stop). Where the reference went on instead, endedEarly says so.
    PathDivergence endedWithoutRouletteDraw(int at) {
        const InspectedVertex* mine = vertex(ours_, at);
        const int depth = mine ? mine->depth : 0;
        const std::string where = vertexName(at) + " (depth " + std::to_string(depth) + ")";
        if (depth >= parameters_.maxDepth)
            return divergence(at, "depth", step(2),
                              "your path ended at " + where +
                                  " without a random number, where the reference drew its "
                                  "roulette number: a depth limit is still there? Lab 4 ends "
                                  "paths only by roulette (maxDepth is " +
                                  std::to_string(parameters_.maxDepth) + ")");
        return divergence(at, "roulette", step(2),
                          "your path ended at " + where +
                              " without a random number from ctx.sampler, where the reference "
                              "drew its roulette number: does your roulette draw come from "
                              "ctx.sampler.get1D()?");
    }

    /// The lab ended its path at `at`; the reference sent a `component` ray from there.
    PathDivergence endedEarly(int at, const std::string& component, const InspectedCall& end) {
        const InspectedVertex* mine = vertex(ours_, at);
        const InspectedVertex* theirs = vertex(theirs_, at);
        const int depth = mine ? mine->depth : 0;
        const std::string where = vertexName(at) + " (depth " + std::to_string(depth) + ")";
        if (lab_.usesRoulette) {
            const std::string draw =
                theirs && theirs->roulette
                    ? " (roulette draw " + threeDigits(theirs->roulette->draw) +
                          " < continueProb " + threeDigits(parameters_.continueProb) + ")"
                    : "";
            if (end.drawsBefore.empty() && depth < parameters_.maxDepth)
                return divergence(at, "roulette", step(2),
                                  "your path ended at " + where +
                                      " without a random number from ctx.sampler, where the "
                                      "reference drew its roulette number and went on" +
                                      draw +
                                      ": does your roulette draw come from "
                                      "ctx.sampler.get1D()?");
            if (depth >= parameters_.maxDepth)
                return divergence(at, "depth", step(2),
                                  "your path ended at " + where + ", the reference went on" + draw +
                                      ": a depth limit is still there? Lab 4 ends paths "
                                      "only by roulette (maxDepth is " +
                                      std::to_string(parameters_.maxDepth) + ")");
            return divergence(at, "roulette", step(2),
                              "your path ended at " + where + ", the reference went on" + draw);
        }
        if (branches()) {
            const bool sentNone = mine && mine->continuedBy.empty();
            if (sentNone && depth < parameters_.maxDepth)
                return divergence(at, "depth", step(2),
                                  "your path ended at " + where + ", the reference sent a " +
                                      component + " ray from there: " + bouncesGoOn());
            return divergence(at, "pick", componentStep(component),
                              "your lab sent no " + component + " ray from " + where +
                                  ", the reference did");
        }
        if (!end.drawsBefore.empty())
            return divergence(at, "pick", pickStep(),
                              "with the same random number " +
                                  threeDigits(end.drawsBefore.front()) + ", your path ended at " +
                                  where + " and the reference sent a " + component + " ray");
        return divergence(at, "depth", step(2),
                          "your path ended at " + where + ", the reference went on with a " +
                              component + " ray: " + bouncesGoOn());
    }

    /// The lab sent a `component` ray from `at`; the reference ended its path there.
    PathDivergence wentOn(int at, const std::string& component) {
        const InspectedVertex* mine = vertex(ours_, at);
        const int depth = mine ? mine->depth : 0;
        const std::string where = vertexName(at) + " (depth " + std::to_string(depth) + ")";
        if (lab_.usesRoulette && mine && mine->roulette &&
            mine->roulette->draw >= parameters_.continueProb)
            return divergence(at, "roulette", step(2),
                              "your path went on from " + where + " with a " + component +
                                  " ray, the reference ended it (roulette draw " +
                                  threeDigits(mine->roulette->draw) + " >= continueProb " +
                                  threeDigits(parameters_.continueProb) + ")");
        if (!lab_.usesRoulette && depth >= parameters_.maxDepth)
            return divergence(at, "depth", step(2),
                              "your lab sent a " + component + " ray from " + where +
                                  ", where the depth limit stops bounces (maxDepth = " +
                                  std::to_string(parameters_.maxDepth) + ")");
        if (branches())
            return divergence(at, "pick", componentStep(component),
                              "your lab sent a " + component + " ray from " + where +
                                  " where the reference sends none (the component is black "
                                  "there?)");
        return divergence(at, "pick", pickStep(),
                          "with the same random numbers, your lab sent a " + component +
                              " ray from " + where + " and the reference ended the path there");
    }

    PathDivergence differentPick(const InspectedVertex& x, const InspectedVertex& y, int at,
                                 const InspectedCall& call) {
        const std::string draw =
            call.drawsBefore.empty() ? "" : " (draw " + threeDigits(call.drawsBefore.front()) + ")";
        const std::string ours = x.arrivedBy == "unknown"
                                     ? "a ray of its own making (not diffuseRay, mirrorRay or "
                                       "refractionRay)"
                                     : "a " + x.arrivedBy + " ray";
        if (branches())
            return divergence(at, "pick", componentStep(y.arrivedBy),
                              "at " + vertexName(at) + " your lab sent " + ours +
                                  " where the reference sent a " + y.arrivedBy + " ray");
        return divergence(at, "pick", pickStep(),
                          "at " + vertexName(at) + ", with the same random numbers" + draw +
                              ", your lab sent " + ours + ", the reference a " + y.arrivedBy +
                              " ray");
    }

    std::optional<PathDivergence> differentWeights() {
        for (size_t v = 0; v < ours_.vertices.size() && v < theirs_.vertices.size(); ++v) {
            const InspectedVertex& x = ours_.vertices[v];
            const InspectedVertex& y = theirs_.vertices[v];
            if (!x.found) continue;
            if (auto divergence = differentEmission(x, y)) return divergence;
            if (x.throughput && y.throughput && !close(*x.throughput, *y.throughput))
                return differentThroughput(x, y);
        }
        if (!close(ours_.contribution, theirs_.contribution))
            return divergence(-1, "value", "",
                              "every vertex's weight agrees with the reference's, but the "
                              "sample's value differs: yours " +
                                  colour(ours_.contribution) + ", the reference's " +
                                  colour(theirs_.contribution));
        return std::nullopt;
    }

    std::optional<PathDivergence> differentEmission(const InspectedVertex& x,
                                                    const InspectedVertex& y) {
        if (!x.emissionWeight || !y.emissionWeight) return std::nullopt;
        const bool ours = !isBlack(*x.emissionWeight), theirs = !isBlack(*y.emissionWeight);
        if (ours == theirs) return std::nullopt;
        const std::string here = isBlack(x.emitted) ? " (this surface emits nothing, but at a "
                                                      "light it counts)"
                                                    : "";
        if (ours)
            return divergence(x.index, "emission", step(1),
                              vertexName(x.index) + " was reached by a " + x.arrivedBy +
                                  " ray and your lab added the emission it found" + here +
                                  ": next-event estimation at the vertex before already counted "
                                  "that light");
        return divergence(x.index, "emission", step(1),
                          "your lab did not add the emission that the " + x.arrivedBy +
                              " ray found at " + vertexName(x.index) + here +
                              ": only a diffuse ray's light is counted by next-event estimation");
    }

    PathDivergence differentThroughput(const InspectedVertex& x, const InspectedVertex& y) {
        const int from = x.parent;
        if (from < 0)
            return divergence(x.index, "value", "",
                              "your lab weights the light found at " + vertexName(x.index) +
                                  " by " + colour(*x.throughput) + ", the reference by " +
                                  colour(*y.throughput));
        const auto probability = [](const InspectedVertex& parent, int child) {
            for (const PathContinuation& c : parent.continuedBy)
                if (c.child == child) return c.probability;
            return std::optional<float>();
        };
        const auto ours = probability(ours_.vertices[static_cast<size_t>(from)], x.index);
        const auto theirs = probability(theirs_.vertices[static_cast<size_t>(from)], y.index);
        const std::string ray = "the " + x.arrivedBy + " ray from " + vertexName(from);
        const std::string stepName = branches()                ? componentStep(x.arrivedBy)
                                     : x.arrivedBy == "glossy" ? glossyStep()
                                                               : step(4);
        if (!ours || !theirs)
            return divergence(from, "probability", stepName,
                              "your lab weights " + ray + " by " + colour(*x.throughput) +
                                  " in all, the reference by " + colour(*y.throughput));
        const float p = parameters_.continueProb;
        std::string text = "your lab divided " + ray + " by " + threeDigits(*ours) +
                           ", the reference by " + threeDigits(*theirs);
        std::string why = stepName;
        const bool near = std::abs(*ours - *theirs) < 0.2f * *theirs;
        if (near && picksByProbability()) {
            // Close but not equal: the probabilities are computed from other strengths.
            text += ": your probabilities are not the reference's (each component's reduceMax "
                    "over their sum)";
            why = step(3);
        } else if (close(*ours, 1.0f) && !close(*theirs, 1.0f))
            text = "your lab did not divide " + ray +
                   " by its probability: the reference "
                   "divides by " +
                   threeDigits(*theirs);
        else if (lab_.usesRoulette && close(*ours * p, *theirs))
            text += ": the pick's probability without continueProb " + threeDigits(p);
        else if (lab_.usesRoulette && close(*ours, p))
            text += ": continueProb without the pick's probability";
        return divergence(from, "probability", why, text);
    }

    PathDivergence divergence(int at, const std::string& kind, const std::string& stepName,
                              const std::string& text) const {
        return {sample_, at, kind, stepName, text};
    }

    static const InspectedVertex* vertex(const InspectedSample& sample, int index) {
        if (index < 0 || static_cast<size_t>(index) >= sample.vertices.size()) return nullptr;
        return &sample.vertices[static_cast<size_t>(index)];
    }

    /// What a depth-limited lab does below maxDepth, in the words of its handout.
    std::string bouncesGoOn() const {
        return "bounces go on from every hit below depth maxDepth = " +
               std::to_string(parameters_.maxDepth);
    }

    static std::string vertexName(int index) {
        return index < 0 ? "the camera" : "vertex " + std::to_string(index);
    }

    static std::string colour(const Color& c) {
        if (c.r == c.g && c.g == c.b) return threeDigits(c.r);
        return "(" + threeDigits(c.r) + ", " + threeDigits(c.g) + ", " + threeDigits(c.b) + ")";
    }

    /// The lab's step n ("lab3.4", numbered as the lab list numbers the labs).
    /// Step n of labs 1-4's order (1 emission, 2 depth or roulette, 3 the pick, 4 the division).
    /// A lab that writes a lobe has those of lab 4 in its step 3 ("as your lab 4") and the
    /// glossy weight in its step 4 (glossyStep).
    std::string step(int n) const {
        if (writesLobe(lab_.identity.lab)) n = 3;
        return "lab" + std::to_string(labNumber(lab_.identity.lab)) + "." + std::to_string(n);
    }
    std::string glossyStep() const {
        return "lab" + std::to_string(labNumber(lab_.identity.lab)) + ".4";
    }
    /// Lab 1 sends a ray for every component that is not black; the others pick one.
    bool branches() const { return lab_.identity.lab == Lab::Branching; }
    /// Labs 3 to 5 pick a component with probabilities that follow its weight.
    bool picksByProbability() const {
        return lab_.identity.lab != Lab::Branching && lab_.identity.lab != Lab::Uniform;
    }
    /// The step that chooses the component: lab 2's uniform pick, lab 3's probabilities, lab 4's
    /// choice as in lab 3.
    std::string pickStep() const { return step(3); }
    /// Lab 1's step for one component's ray.
    std::string componentStep(const std::string& component) const {
        if (component == "diffuse") return step(3);
        if (component == "mirror") return step(4);
        if (component == "refraction") return step(5);
        return "";
    }

    const PixelInspection& lab_;
    const LabParameters& parameters_; ///< the lab's maxDepth and continueProb
    size_t sample_;
    const InspectedSample& ours_;
    const InspectedSample& theirs_;
};

/// The random numbers a sample's path drew from ctx.sampler.
size_t drawsOf(const InspectedSample& sample) {
    size_t draws = 0;
    for (const InspectedCall& call : sample.calls) draws += call.drawsBefore.size();
    return draws;
}

/// Whether a sample's path traced a ray after the camera's: a lab that never bounces (a stub)
/// needs no random number, and is told what it does not trace rather than where its numbers
/// come from.
bool bounced(const InspectedSample& sample) {
    return std::count_if(sample.calls.begin(), sample.calls.end(),
                         [](const InspectedCall& call) { return call.type == "trace"; }) > 1;
}

} // namespace

PathComparison comparePaths(const PixelInspection& lab, const PixelInspection& reference) {
    PathComparison comparison;
    const size_t samples = std::min(lab.samples.size(), reference.samples.size());
    // A lab that takes none of its numbers from ctx.sampler has paths unrelated to the
    // reference's: any first difference would be chance.
    size_t ours = 0, theirs = 0;
    bool labBounced = false;
    for (size_t s = 0; s < samples; ++s) {
        ours += drawsOf(lab.samples[s]);
        theirs += drawsOf(reference.samples[s]);
        labBounced = labBounced || bounced(lab.samples[s]);
    }
    if (ours == 0 && theirs > 0 && labBounced) {
        comparison.samplesCompared = samples;
        comparison.comparable = false;
        comparison.divergence = PathDivergence{
            0, -1, "own-random", "",
            "your lab drew no random number from ctx.sampler, where the reference drew " +
                std::to_string(theirs) +
                " in these samples: its random numbers come from "
                "elsewhere, so its paths cannot be compared with the reference's draw by draw, "
                "and its images cannot be made again from the seed (handout 00: random numbers "
                "come from ctx.sampler only)"};
        return comparison;
    }
    for (size_t s = 0; s < samples; ++s) {
        ++comparison.samplesCompared;
        SampleWalk walk(lab, reference, s);
        if (auto divergence = walk.firstDifference(comparison.comparable)) {
            comparison.divergence = divergence;
            break;
        }
    }
    return comparison;
}

std::string describeComparison(const PathComparison& comparison, const PixelInspection& lab) {
    const std::string pixel =
        "pixel (" + std::to_string(lab.x) + ", " + std::to_string(lab.y) + ")";
    if (!comparison.divergence)
        return "The reference replayed " + std::to_string(comparison.samplesCompared) +
               " sample(s) of " + pixel +
               " with the same random numbers: every path and value "
               "agrees with yours.";
    const PathDivergence& d = *comparison.divergence;
    std::string text = "Replayed with the reference on " + pixel + ", sample " +
                       std::to_string(lab.samples[d.sample].index) + ": " + d.text;
    if (!d.step.empty()) text += " (TODO " + d.step + ")";
    return text + ".";
}

} // namespace pathlab
