#pragma once
/// Peak memory of a progressive render at full-HD size, measured in a child process so that
/// nothing the benchmark itself holds is counted.

#include "bench_options.h"
#include "bench_scene.h"

#include <string>

namespace pathlab::bench {

struct MemoryFigures {
    bool measured = false;
    std::string note; ///< why it was not measured
    int width = 0, height = 0, frames = 0;
    double peakMiB = 0; ///< the child's maximum resident set size
};

/// Runs `self --memory-probe ...` (this program) on `scene` and reads its peak resident memory.
MemoryFigures measurePeakMemory(const std::string& self, const BenchScene& scene,
                                const BenchOptions& options);

/// The child's side: renders options.memoryFrames frames of one sample per pixel of `scene` at
/// options.memoryWidth × memoryHeight with the viewer's progressive renderer, taking each
/// finished frame and converting it for display as the viewer's window does, only without a
/// window. Returns the exit status.
int runMemoryProbe(const BenchScene& scene, const BenchOptions& options);

} // namespace pathlab::bench
