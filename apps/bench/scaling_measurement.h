#pragma once
/// How the renderer would scale past this machine's cores, from what can be measured on it: one
/// solution at 1 thread up to more threads than cores, at several tile sizes, and the serial
/// work the window's render thread does between two frames' passes. By wall-clock time: scaling
/// is about how soon a pass is done.

#include "bench_scene.h"
#include "scene_measurement.h"

#include <string>
#include <vector>

namespace pathlab::bench {

struct ScalingFigures {
    std::string scene;
    Lab lab = Lab::Roulette;
    int width = 0, height = 0, passes = 0;
    struct Point {
        int value;           ///< threads, or pixels per tile side
        RenderTiming timing; ///< the fastest of the 1-spp passes by wall-clock time

        double samplesPerSecond() const { return timing.samplesPerSecond(); }
    };
    std::vector<Point> byThreads;  ///< at the default tile size
    int tileThreads = 0;           ///< the threads of byTileSize
    std::vector<Point> byTileSize; ///< at tileThreads threads
    /// The window's serial work per frame at this size: the image's figures
    /// (AccumulationBuffer::summary) and its mean copied for display (meanImage).
    double handOffSeconds = 0;

    /// The share of a frame the hand-off would take at `threads` threads, if the pass's
    /// samples/s went on growing as from 1 thread to tileThreads.
    double handOffShare(int threads) const;
};

/// Measures `lab`'s reference solution on `scene` at settings' size, 1-spp passes as the window
/// renders them, `settings.passes` each: at 1, 2, 4 and 8 threads (and `cores` if more) and at
/// tiles of 8 to 64 pixels with `cores` threads.
ScalingFigures measureScaling(const BenchScene& scene, const SceneSettings& settings, Lab lab,
                              int cores);

} // namespace pathlab::bench
