#pragma once
/// Embree's own path tracer (`pathtracer` from Debian's embree-tools), run headless.
///
/// It follows paths of at most --max-path-length hits (1 = the primary hit and its shadow ray),
/// with next-event estimation at every hit, diffuse bounces sampled by the cosine and no Russian
/// roulette: on a diffuse-only scene its --max-path-length N traces the same paths as PathLab's
/// importance lab at --max-depth N-1. Its point lights are intensities, as PathLab's. It writes
/// each pixel's mean, clamped to [0,1], linear (no gamma) in 8 bits: floor(255.01·value).

#include "bench_scene.h"

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

/// Samples per second of its fastest frame of `spp` samples per pixel, out of `frames` frames
/// after one warm-up frame (its --benchmark mode, which times frames the same way PathLab's
/// benchmark times passes). Throws std::runtime_error if it fails.
double pathtracerSamplesPerSecond(const PathtracerJob& job, int spp, int frames);

/// Its image at `spp` samples per pixel as it writes it (values k/255), RGB, row-major.
/// `folder` receives the temporary image file. Throws std::runtime_error if it fails.
std::vector<float> pathtracerImage(const PathtracerJob& job, int spp, const std::string& folder);

/// A linear radiance as the pathtracer stores it: clamped to [0,1], then 8 bits by truncation.
float embreeStoredValue(float radiance);

} // namespace pathlab::bench
