#pragma once
/// How long the viewer's window takes to show something: from the program's start to the first
/// frame it receives and to the first image on screen, under a virtual display (Xvfb).

#include "bench_options.h"
#include "bench_scene.h"

#include <string>

namespace pathlab::bench {

struct FirstFrameLatency {
    bool measured = false;
    std::string note; ///< why it was not measured
    int runs = 0;     ///< viewer starts; the median of each figure counts
    int width = 0, height = 0;
    double firstFrameMs = 0; ///< start to the first frame in the window's hands
    double firstImageMs = 0; ///< start to the first image on screen (after glFinish)
};

/// Starts `viewer` (the importance solution on `scene`, at the window's default size) under
/// xvfb-run, `runs` times, and reads the latencies it prints with --print-frame-rate. Not
/// measured (with a note) without xvfb-run, or when `runs` is 0.
FirstFrameLatency measureFirstFrame(const std::string& viewer, const BenchScene& scene, int runs);

} // namespace pathlab::bench
