#pragma once
/// What a headless render measured, written as JSON for scripts and the grader.

#include "pathlab/color.h"
#include "pathlab/ray_counters.h"

#include <cstdint>
#include <string>

namespace pathlab {

struct RenderStats {
    std::string scene, lab, impl;
    int spp = 0, width = 0, height = 0;
    uint64_t seed = 0;
    int maxDepth = 0;
    float continueProb = 0;
    int threads = 0;
    double seconds = 0;            ///< wall time of rendering alone (no loading, no writing)
    RayCounters rays;
    Color meanRadiance;
    Color meanVariance;            ///< per-sample variance averaged over pixels, per channel
    int nonfinitePixels = 0;

    double samplesPerSecond() const;
    double raysPerSecond() const;
};

/// Writes `stats` as one JSON object with the fields DESIGN.md lists (plus max_depth,
/// continue_prob, threads and mean_variance). Atomic, like images.
void writeRenderStats(const std::string& path, const RenderStats& stats);

/// Writes `text` to `path` through a temporary file in the same folder and a rename.
void writeFileAtomically(const std::string& path, const std::string& text);

} // namespace pathlab
