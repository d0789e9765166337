#include "pathlab/inspect/pick_test.h"

#include "pathlab/inspect/inspection_numbers.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace pathlab {

namespace {

/// Materials told apart by their components (a Material has no name).
using MaterialKey = std::tuple<float, float, float, float, float, float, float, float, float>;

MaterialKey keyOf(const Material& m) {
    return {m.Kd.r, m.Kd.g, m.Kd.b, m.Ks.r, m.Ks.g, m.Ks.b, m.Kt.r, m.Kt.g, m.Kt.b};
}

bool canChoose(const InspectedVertex& v, const PixelInspection& inspection) {
    if (!v.found) return false;
    if (isBlack(v.material.Kd) && isBlack(v.material.Ks) && isBlack(v.material.Kt)) return false;
    const bool depthLimited = !inspection.usesRoulette;
    return !depthLimited || v.depth < inspection.identity.parameters.maxDepth;
}

/// Adds the vertex's choice to `picks`; false where it says nothing of a pick (several rays, a
/// ray the lab made itself, total internal reflection). A pick counts whether or not its
/// division was measured (a ray that left the scene brings no light to measure it by); what it
/// divided by is kept where it was, and is a division (not another component's colour).
bool tally(const InspectedVertex& v, MaterialPicks& picks) {
    if (v.continuedBy.size() > 1) return false;
    if (v.continuedBy.empty()) {
        ++picks.visits;
        ++picks.ended;
        return true;
    }
    const PathContinuation& c = v.continuedBy.front();
    std::string component = c.component;
    // Total internal reflection: refraction's ray is the mirror's, and which was picked is
    // clear only where the material has one of the two.
    if (component == "specular" && isBlack(v.material.Ks)) component = "refraction";
    if (component == "specular" && isBlack(v.material.Kt)) component = "mirror";
    const bool known = component == "diffuse" || component == "mirror" || component == "refraction";
    if (!known) return false;
    auto it = std::find_if(picks.components.begin(), picks.components.end(),
                           [&](const ComponentPicks& p) { return p.component == component; });
    if (it == picks.components.end()) {
        picks.components.push_back({component, 0, {}});
        it = picks.components.end() - 1;
    }
    ++it->picked;
    if (c.probability && *c.probability > 0 && c.weightedBy.empty())
        it->dividedBy.push_back(*c.probability);
    ++picks.visits;
    return true;
}

void fit(MaterialPicks& m) {
    std::vector<double> observed, expected;
    for (const ComponentPicks& c : m.components) {
        observed.push_back(c.picked);
        expected.push_back(m.visits * static_cast<double>(c.claimedProbability()));
        m.claimedTotal += c.claimedProbability();
    }
    observed.push_back(m.ended);
    expected.push_back(m.visits * std::max(0.0, 1 - m.claimedTotal));
    m.fit = chiSquareFit(observed, expected);
}

/// The line for a material whose picks and divisions disagree: its component furthest from
/// what the lab divided by.
std::string problemOf(const MaterialPicks& m) {
    const std::string where =
        "at " + m.name + " (" + std::to_string(m.visits) + " visits) you went on by ";
    if (m.claimedTotal > 1.001)
        return "at " + m.name + " you divide by probabilities that add up to " +
               threeDigits(m.claimedTotal) + ", more than 1";
    const ComponentPicks* worst = nullptr;
    double worstScore = -1;
    for (const ComponentPicks& c : m.components) {
        const double expected = m.visits * static_cast<double>(c.claimedProbability());
        const double score = std::abs(c.picked - expected) / std::sqrt(std::max(expected, 1.0));
        if (score > worstScore) worstScore = score, worst = &c;
    }
    if (!worst) return "at " + m.name + " your lab ended every path";
    return where + worst->component + " with frequency " +
           threeDigits(static_cast<double>(worst->picked) / m.visits) + " and divided by " +
           threeDigits(worst->claimedProbability());
}

} // namespace

float ComponentPicks::claimedProbability() const {
    if (dividedBy.empty()) return 0;
    std::vector<float> sorted = dividedBy;
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    return sorted[sorted.size() / 2];
}

PickTestResult testPicks(const std::vector<PixelInspection>& inspections, double alpha,
                         int minVisits) {
    PickTestResult result;
    result.minVisits = minVisits;
    result.alpha = alpha;
    std::map<MaterialKey, MaterialPicks> byMaterial;
    bool branches = false;
    for (const PixelInspection& inspection : inspections)
        for (const InspectedSample& sample : inspection.samples)
            for (const InspectedVertex& v : sample.vertices) {
                if (!canChoose(v, inspection)) continue;
                branches = branches || v.continuedBy.size() > 1;
                MaterialPicks& picks = byMaterial[keyOf(v.material)];
                picks.material = v.material;
                tally(v, picks);
            }
    for (auto& [key, picks] : byMaterial)
        if (picks.visits >= minVisits) result.materials.push_back(std::move(picks));
    std::sort(result.materials.begin(), result.materials.end(),
              [](const MaterialPicks& a, const MaterialPicks& b) { return a.visits > b.visits; });
    // A lab that went on by no component (a stub) picks nothing: nothing to test.
    const bool picked = std::any_of(result.materials.begin(), result.materials.end(),
                                    [](const MaterialPicks& m) { return !m.components.empty(); });
    result.applies = !branches && picked;
    if (!result.applies) return result;
    result.alphaEach = sidakAlpha(alpha, static_cast<int>(result.materials.size()));
    for (MaterialPicks& m : result.materials) {
        m.name = materialText(m.material);
        fit(m);
        if (m.fit.pValue < result.alphaEach || m.claimedTotal > 1.001)
            result.problems.push_back(problemOf(m));
    }
    result.passed = result.problems.empty();
    return result;
}

std::string describePickTest(const PickTestResult& result) {
    if (!result.applies)
        return "pick test: nothing to test (a lab that sends a ray for every component picks "
               "none, as does one that goes on by none yet; or no material was met " +
               std::to_string(result.minVisits) + " times)\n";
    std::string text = "pick test: how often your lab went on by each component, against the "
                       "probability it divided by (chi-square per material; a right lab fails "
                       "with probability " +
                       threeDigits(result.alpha) + ")\n";
    for (const MaterialPicks& m : result.materials) {
        text += "  " + m.name + ": " + std::to_string(m.visits) + " visits:";
        for (const ComponentPicks& c : m.components)
            text += " " + c.component + " " +
                    threeDigits(static_cast<double>(c.picked) / m.visits) + " (divided by " +
                    threeDigits(c.claimedProbability()) + "),";
        text += " ended " + threeDigits(static_cast<double>(m.ended) / m.visits) +
                "; p = " + threeDigits(m.fit.pValue) + "\n";
    }
    text += result.passed ? "passed: every material's picks follow what your lab divides by\n"
                          : "FAILED:\n";
    for (const std::string& problem : result.problems) text += "  " + problem + "\n";
    return text;
}

} // namespace pathlab
