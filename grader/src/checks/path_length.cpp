#include "checks/path_length.h"

#include <cmath>
#include <cstdio>

namespace pathlab::grader {

namespace {

/// Within 10% (and 0.05) of q/(1-q): the observed means hold millions of paths, whose count of
/// bounces has variance q/(1-q)^2, so a correct lab is within a fraction of a percent.
bool matchesRoulette(const PathLengthObservation& o) {
    const double expected = expectedBounceRays(o.continueProb);
    return std::fabs(o.bounceRays - expected) <= 0.1 * expected + 0.05;
}

std::string listed(const std::vector<PathLengthObservation>& observations, bool expected) {
    std::string text;
    for (const PathLengthObservation& o : observations) {
        char one[96];
        std::snprintf(one, sizeof one, "%s%.2f at continueProb %.2g", text.empty() ? "" : ", ",
                      expected ? expectedBounceRays(o.continueProb) : o.bounceRays, o.continueProb);
        text += one;
    }
    return text;
}

} // namespace

double expectedBounceRays(double continueProb) { return continueProb / (1 - continueProb); }

std::string ignoredContinueProb(const std::vector<PathLengthObservation>& observations) {
    if (observations.size() < 2) return "";
    double shortest = INFINITY, longest = 0, lowestQ = 1, highestQ = 0;
    for (const PathLengthObservation& o : observations) {
        shortest = std::fmin(shortest, o.bounceRays);
        longest = std::fmax(longest, o.bounceRays);
        lowestQ = std::fmin(lowestQ, o.continueProb);
        highestQ = std::fmax(highestQ, o.continueProb);
    }
    // Paths that do not lengthen (within 25%) while q/(1-q) grows several times over. A lab
    // with no bounce at all is not ignoring continueProb but missing its bounces: the furnaces'
    // values tell that cause.
    const bool parametersDiffer = expectedBounceRays(highestQ) > 2 * expectedBounceRays(lowestQ);
    if (!parametersDiffer || shortest < 0.02 || longest > 1.25 * shortest + 0.05) return "";
    bool anyWrong = false;
    for (const PathLengthObservation& o : observations) anyWrong = anyWrong || !matchesRoulette(o);
    if (!anyWrong) return "";
    return "ctx.continueProb ignored: the paths are as long at one continueProb as at the other "
           "(bounce rays per sample in the furnace: " +
           listed(observations, false) +
           "), where continuing with probability continueProb at every hit gives " +
           listed(observations, true) + " (TODO lab4.2)";
}

std::string pathLengthNote(const std::vector<PathLengthObservation>& observations) {
    for (const PathLengthObservation& o : observations)
        if (!matchesRoulette(o))
            return "note: the paths' lengths do not follow continueProb as lab 4 specifies "
                   "(bounce rays per sample in the furnace: " +
                   listed(observations, false) +
                   "; continuing with probability continueProb at every hit gives " +
                   listed(observations, true) +
                   "): the mean is right, the estimator is not "
                   "the handout's (TODO lab4.2)";
    return "";
}

} // namespace pathlab::grader
