#pragma once
/// The knobs of the labs, set from the command line or the viewer.

#include "pathlab/light_sample.h"

namespace pathlab {

struct LabParameters {
    int maxDepth = 3;          ///< labs 1–3: bounces after the primary hit (which is depth 0)
    float continueProb = 0.1f; ///< lab 4: probability that Russian roulette continues a path
    /// lab 6: both strategies, weighted by the lab's heuristic, or one alone (--strategy)
    StrategyChoice strategies = StrategyChoice::Both;
};

} // namespace pathlab
