#include "pathlab/inspect/inspection_table.h"

#include "pathlab/inspect/inspection_numbers.h"

#include <cstdio>
#include <cstdlib>

namespace pathlab {

namespace {

/// A roulette draw, with the digits it takes to stay on its side of continueProb and below 1:
/// 0.9996 is not "1".
std::string drawNumber(float draw, float continueProb) {
    char text[32];
    for (int digits = 3; digits <= 9; ++digits) {
        std::snprintf(text, sizeof text, "%.*g", digits, draw);
        const float shown = std::strtof(text, nullptr);
        if ((shown < continueProb) == (draw < continueProb) && (shown < 1) == (draw < 1)) break;
    }
    return text;
}

std::string wentOn(const InspectedVertex& v) {
    std::string text;
    for (const PathContinuation& c : v.continuedBy) {
        if (!text.empty()) text += " ";
        // A weight that is another component's colour is no division: said as what it is.
        text += c.component + "→" + std::to_string(c.child) +
                (!c.weightedBy.empty() ? " weighted by " + c.weightedBy
                 : c.probability       ? " /" + threeDigits(*c.probability)
                                       : std::string(" /?"));
    }
    if (v.roulette) {
        // The lab's first draw at the vertex, taken as its roulette draw: where going on and
        // the draw disagree, the table says so (a kept depth limit, a draw from elsewhere).
        const bool below = v.roulette->draw < v.roulette->continueProb;
        text += std::string(text.empty() ? "" : " ") + "(roulette " +
                drawNumber(v.roulette->draw, v.roulette->continueProb) + (below ? " < " : " >= ") +
                threeDigits(v.roulette->continueProb) + ")";
        // A surface that scatters nothing (a light's, all of Kd, Ks and Kt black) ends the path
        // whatever the draw said.
        const Material& m = v.material;
        const bool canScatter = !isBlack(m.Kd) || !isBlack(m.Ks) || !isBlack(m.Kt);
        if (below != v.roulette->wentOn && (canScatter || !below))
            text += below ? " ENDED although the draw is below continueProb"
                          : " WENT ON although the draw is not below continueProb";
    }
    if (!text.empty()) return text;
    // Why it ended is the lab's: its draws there say what it decided on (a pick that fell on a
    // black component, a roulette draw).
    std::string drew;
    for (const float draw : v.draws) drew += (drew.empty() ? "" : ",") + threeDigits(draw);
    return drew.empty() ? "ends" : "ends (drew " + drew + ")";
}

/// What the lab's own parameters say of a vertex's end: in labs 1-3 no ray goes on from depth
/// maxDepth; in lab 4 a path ends only by a roulette draw.
std::string depthNote(const InspectedVertex& v, const PixelInspection& inspection) {
    if (inspection.usesRoulette)
        return !v.roulette && v.continuedBy.empty()
                   ? " ENDED without a random number drawn (its roulette not written yet, or a "
                     "depth limit kept?)"
                   : "";
    if (v.depth < inspection.identity.parameters.maxDepth || v.continuedBy.empty()) return "";
    return " WENT ON from depth " + std::to_string(v.depth) + " = maxDepth";
}

void appendRow(std::string& out, const char* format, const std::string& a, const std::string& b,
               const std::string& c, const std::string& d, const std::string& e,
               const std::string& f, const std::string& g, const std::string& h) {
    char line[512];
    std::snprintf(line, sizeof line, format, a.c_str(), b.c_str(), c.c_str(), d.c_str(), e.c_str(),
                  f.c_str(), g.c_str(), h.c_str());
    out += line;
}

} // namespace

std::string inspectionTable(const PixelInspection& inspection) {
    const char* format = "  %-3s %-11s %-4s %-24s %-18s %-18s %-20s %s\n";
    std::string out = labAndImplementation(inspection.identity) + ", pixel (" +
                      std::to_string(inspection.x) + ", " + std::to_string(inspection.y) +
                      "), seed " + std::to_string(inspection.identity.seed) + "\n";
    bool nonLinear = false;
    for (const InspectedSample& sample : inspection.samples) {
        out += "sample " + std::to_string(sample.index) + ": value " +
               compactColour(sample.contribution) + "\n";
        for (const InspectedVertex& v : sample.vertices) nonLinear = nonLinear || !v.linear;
        appendRow(out, format, "v", "arrived by", "from", "material", "throughput", "emission +",
                  "direct +", "went on by / divided by");
        for (const InspectedVertex& v : sample.vertices) {
            const std::string from = v.parent < 0 ? "-" : std::to_string(v.parent);
            if (!v.found) {
                appendRow(out, format, std::to_string(v.index), v.arrivedBy, from,
                          "(left the scene)", "", "", "", "");
                continue;
            }
            appendRow(
                out, format, std::to_string(v.index), v.arrivedBy, from, materialText(v.material),
                v.throughput ? compactColour(*v.throughput) + (v.linear ? "" : " NOT LINEAR") : "?",
                compactColour(v.emissionAdded),
                v.directLightCalled ? compactColour(v.directLightAdded) : "not asked",
                wentOn(v) + depthNote(v, inspection));
        }
    }
    if (nonLinear)
        out +=
            "NOT LINEAR: your lab's value does not grow in proportion to the light found at a\n"
            " vertex (twice the light, not twice the value): a clamp, a min() or a cap on what a\n"
            " ray brings back? A clamp is biased, and the weights and probabilities measured\n"
            " there mean nothing (the grader's light-linearity check says the same).\n";
    bool weightedByOther = false;
    for (const InspectedSample& sample : inspection.samples)
        for (const InspectedVertex& v : sample.vertices)
            for (const PathContinuation& c : v.continuedBy)
                weightedByOther = weightedByOther || !c.weightedBy.empty();
    out +=
        "(throughput: the weight the lab gave light found at the vertex; emission + and direct +:\n"
        " what it added there; went on by: the ray to the next vertex and the probability divided\n"
        " by, ? where it cannot be measured: a ray that left the scene, a vertex NOT LINEAR, a\n"
        " glossy ray (weighted by f cos θ / p, not by one probability)" +
        std::string(weightedByOther ? ";\n weighted by Kt: the ray's weight is another component's "
                                      "colour, not its own's.)\n"
                                    : ".)\n");
    return out;
}

} // namespace pathlab
