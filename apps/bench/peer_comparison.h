#pragma once
/// PathLab next to Embree's own pathtracer on Embree's Cornell box: speed and mean radiance.

#include "bench_options.h"
#include "busy_machine.h"

#include "pathlab/color.h"

#include <string>
#include <vector>

namespace pathlab::bench {

struct PeerComparison {
    bool measured = false;
    std::string note; ///< why it was not measured
    std::string scene;
    int width = 0, height = 0, spp = 0, imageSpp = 0, threads = 0;
    int frames = 0, rounds = 0; ///< timed frames per round; each tracer's fastest counts
    int maxPathLength = 0;      ///< Embree's; PathLab's importance lab runs at maxDepth one less
    float lightScale = 1;
    /// Samples per second of each's fastest frame (wall-clock time: how soon a frame is done).
    double embreeSamplesPerSecond = 0, oursSamplesPerSecond = 0;
    /// Samples per CPU-second of each's whole process, the best round (the speed to compare:
    /// other programs on the machine change it little). Embree's from two runs' CPU time
    /// differenced (PathtracerSpeed), PathLab's from its pass's; both count the threads' waits
    /// for work as well as their rendering.
    double embreeSamplesPerCpuSecond = 0, oursSamplesPerCpuSecond = 0;
    /// Embree's CPU time per frame in each round, and its start-up's (with the warm-up frame):
    /// how steady the differencing was.
    std::vector<double> embreeCpuSecondsPerFrame;
    double embreeStartCpuSeconds = 0;
    /// Why there is no CPU-time comparison ("" when there is): Embree's frames too short.
    std::string cpuNote;
    /// What each's threads had of the machine in the round of its best CPU rate (Embree's per
    /// frame, on average).
    CpuUse embreeCpuUse, oursCpuUse;
    Color embreeMean, oursMean; ///< means of the two images as Embree stores them (8 bits)
    Color standardError;        ///< of the difference of the two means
    float oursMaxPixel = 0;     ///< PathLab's largest pixel value: below 1, nothing clipped

    /// PathLab's samples per CPU-second over Embree's: the comparison of their speed.
    double cpuRatio() const {
        return embreeSamplesPerCpuSecond > 0 ? oursSamplesPerCpuSecond / embreeSamplesPerCpuSecond
                                             : 0;
    }
    /// The same by wall-clock time.
    double ratio() const {
        return embreeSamplesPerSecond > 0 ? oursSamplesPerSecond / embreeSamplesPerSecond : 0;
    }
};

/// Times Embree's pathtracer at `pathLength` and PathLab's importance solution at max-depth
/// pathLength - 1 on the peer scene of `options`, with equal size, samples per pixel and
/// threads (by CPU time and by wall-clock time), and compares their images' means. Not measured
/// (with a note) when the pathtracer or its scene is not installed.
PeerComparison comparePeer(const BenchOptions& options, int threads, int pathLength);

} // namespace pathlab::bench
