#pragma once
/// Embree's own path tracer (`pathtracer` from Debian's embree-tools), run headless.
///
/// It follows paths of at most --max-path-length hits (1 = the primary hit and its shadow ray),
/// with next-event estimation at every hit, diffuse bounces sampled by the cosine and no Russian
/// roulette: on a diffuse-only scene its --max-path-length N traces the same paths as PathLab's
/// importance lab at --max-depth N-1. Its point lights are intensities, as PathLab's. It writes
/// each pixel's mean, clamped to [0,1], linear (no gamma) in 8 bits: floor(255.01·value).

#include "bench_scene.h"

#include <algorithm>
#include <string>
#include <vector>

namespace pathlab::bench {

/// What the pathtracer is asked to render.
struct PathtracerJob {
    std::string program; ///< the pathtracer executable
    BenchScene scene;
    int width, height;
    int maxPathLength;
    int threads;
};

/// Its speed at one number of samples per pixel, by both clocks.
struct PathtracerSpeed {
    double samplesPerSecond = 0; ///< of its fastest frame, as it times frames itself
    double framesPerSecond = 0;  ///< its frames' mean rate, for the share of its cores it had
    /// Its whole process's CPU time (user and system) per frame: the CPU time of a run of
    /// `frames` frames less that of a run of none, over `frames`. The runs' start-up (loading,
    /// Embree's BVH build, threads starting, the warm-up frame) cancels.
    double cpuSecondsPerFrame = 0;
    double startCpuSeconds = 0; ///< the run of no frames: start-up and the warm-up frame
    /// 0 when the timed frames took too little CPU time beside the start-up's to be told apart
    /// from its variation (less than four times it).
    double samplesPerCpuSecond = 0;

    /// The start-up alone: the run of no frames less its warm-up frame.
    double startUpCpuSeconds() const { return std::max(0.0, startCpuSeconds - cpuSecondsPerFrame); }
};

/// Its speed for frames of `spp` samples per pixel: `frames` frames after one warm-up frame (its
/// --benchmark mode, which times frames as PathLab's benchmark times passes), and its CPU time
/// from that run and one of the warm-up frame alone. Throws std::runtime_error if it fails.
PathtracerSpeed pathtracerSpeed(const PathtracerJob& job, int spp, int frames);

/// Its image at `spp` samples per pixel as it writes it (values k/255), RGB, row-major.
/// `folder` receives the temporary image file. Throws std::runtime_error if it fails.
std::vector<float> pathtracerImage(const PathtracerJob& job, int spp, const std::string& folder);

/// A linear radiance as the pathtracer stores it: clamped to [0,1], then 8 bits by truncation.
float embreeStoredValue(float radiance);

} // namespace pathlab::bench
