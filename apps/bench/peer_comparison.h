#pragma once
/// PathLab next to Embree's own pathtracer on Embree's Cornell box: speed and mean radiance.

#include "bench_options.h"

#include "pathlab/color.h"

#include <string>

namespace pathlab::bench {

struct PeerComparison {
    bool measured = false;
    std::string note; ///< why it was not measured
    std::string scene;
    int width = 0, height = 0, spp = 0, imageSpp = 0, threads = 0;
    int frames = 0, rounds = 0; ///< timed frames per round; each tracer's fastest counts
    int maxPathLength = 0;      ///< Embree's; PathLab's importance lab runs at maxDepth one less
    float lightScale = 1;
    double embreeSamplesPerSecond = 0, oursSamplesPerSecond = 0;
    Color embreeMean, oursMean; ///< means of the two images as Embree stores them (8 bits)
    Color standardError;        ///< of the difference of the two means
    float oursMaxPixel = 0;     ///< PathLab's largest pixel value: below 1, nothing clipped

    double ratio() const {
        return embreeSamplesPerSecond > 0 ? oursSamplesPerSecond / embreeSamplesPerSecond : 0;
    }
};

/// Times Embree's pathtracer at `pathLength` and PathLab's importance solution at max-depth
/// pathLength - 1 on the peer scene of `options`, with equal size, samples per pixel and
/// threads, and compares their images' means. Not measured (with a note) when the pathtracer or
/// its scene is not installed.
PeerComparison comparePeer(const BenchOptions& options, int threads, int pathLength);

} // namespace pathlab::bench
