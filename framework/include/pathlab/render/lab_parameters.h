#pragma once
/// The knobs of the four labs, set from the command line or the viewer.

namespace pathlab {

struct LabParameters {
    int maxDepth = 3;          ///< labs 1–3: bounces after the primary hit (which is depth 0)
    float continueProb = 0.1f; ///< lab 4: probability that Russian roulette continues a path
};

} // namespace pathlab
