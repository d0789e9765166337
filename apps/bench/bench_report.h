#pragma once
/// The benchmark's figures as tables for people and as JSON for tracking them over time.

#include "first_frame.h"
#include "memory_probe.h"
#include "peer_comparison.h"
#include "scaling_measurement.h"
#include "scene_measurement.h"

#include <cstdio>
#include <string>
#include <vector>

namespace pathlab::bench {

struct BenchReport {
    std::vector<SceneFigures> scenes;
    std::vector<PeerComparison> peers; ///< one per path length
    FirstFrameLatency firstFrame;
    MemoryFigures memory;
    std::vector<ScalingFigures> scaling; ///< empty with --peer-only
};

/// One table per scene, then the comparison with Embree's pathtracer, scaling and memory.
void printReport(const BenchReport& report, std::FILE* out);

/// The same figures as one JSON document (rates per second and, in the keys that say so, per
/// CPU-second; memory in MiB).
std::string reportJson(const BenchReport& report);

} // namespace pathlab::bench
