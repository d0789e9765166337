#include "pathlab/render/render_identity.h"

#include <cstdio>

namespace pathlab {

bool operator==(const RenderIdentity& a, const RenderIdentity& b) {
    return a.lab == b.lab && a.implementation == b.implementation &&
           a.parameters.maxDepth == b.parameters.maxDepth &&
           a.parameters.continueProb == b.parameters.continueProb &&
           a.parameters.strategies == b.parameters.strategies && a.seed == b.seed &&
           a.width == b.width && a.height == b.height;
}

std::vector<std::string> renderIdentityArguments(const RenderIdentity& identity) {
    // Nine significant digits tell every float apart: the viewer reads back the very
    // continueProb asked for (std::to_string's six decimals would round 0.1234567 to 0.123457).
    char continueProb[32];
    std::snprintf(continueProb, sizeof continueProb, "%.9g",
                  static_cast<double>(identity.parameters.continueProb));
    std::vector<std::string> arguments = {"--lab",
                                          std::string(labName(identity.lab)),
                                          "--max-depth",
                                          std::to_string(identity.parameters.maxDepth),
                                          "--continue-prob",
                                          continueProb,
                                          "--seed",
                                          std::to_string(identity.seed),
                                          "--size",
                                          std::to_string(identity.width),
                                          std::to_string(identity.height)};
    if (identity.implementation == Implementation::Solution) arguments.push_back("--solution");
    // Only where it is not the default, so that labs 1-5's arguments stay as they were.
    if (identity.parameters.strategies == StrategyChoice::LightOnly)
        arguments.insert(arguments.end(), {"--strategy", "light"});
    if (identity.parameters.strategies == StrategyChoice::LobeOnly)
        arguments.insert(arguments.end(), {"--strategy", "lobe"});
    return arguments;
}

std::string labAndImplementation(const RenderIdentity& identity) {
    return std::string(labName(identity.lab)) + " (" +
           std::string(implementationName(identity.implementation)) + ")";
}

} // namespace pathlab
