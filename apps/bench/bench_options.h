#pragma once
/// What `bench` measures and how, from its command line.

#include "pathlab/render/lab_parameters.h"

#include <string>
#include <vector>

namespace pathlab::bench {

struct BenchOptions {
    std::vector<std::string> scenes; ///< --scene FILE.ecs (repeatable); default: the VI2 box
    int width = 512, height = 512;   ///< --size W H of every timed render
    int spp = 2;                     ///< --spp: samples per pixel of one timed pass
    /// --passes: timed passes after a warm-up; the one of least CPU time counts (the fastest by
    /// wall-clock time in the scaling figures)
    int passes = 3;
    int threads = 0;          ///< --threads for the multi-threaded figures (0: all cores)
    LabParameters parameters; ///< --max-depth, --continue-prob
    std::string jsonFile;     ///< --json FILE: the results as JSON as well

    // Embree's own path tracer, on its Cornell box.
    // By default where embree-tools puts them for the Embree built against (CMakeLists.txt).
    std::string pathtracer = PATHLAB_EMBREE_PATHTRACER; ///< --pathtracer; --no-pathtracer skips it
    std::string peerScene = PATHLAB_EMBREE_MODELS_DIR "/cornell_box.ecs"; ///< --peer-scene
    float peerLightScale = 0.1f; ///< --peer-light-scale: dims the scene's point lights
    int peerSpp = 4;             ///< --peer-spp: samples per pixel of one timed frame
    int peerImageSpp = 16;       ///< --peer-image-spp: of the images whose means are compared
    /// --peer-path-lengths: Embree's path lengths compared (PathLab's importance solution at
    /// max-depth one less).
    std::vector<int> peerPathLengths = {2, 4, 8};
    bool peerOnly = false; ///< --peer-only: just the comparison with Embree's tracer

    int firstFrameRuns = 3; ///< --first-frame-runs N: viewer starts under Xvfb (0 skips them)

    // Peak memory of a progressive render, measured in a child process.
    int memoryWidth = 1920, memoryHeight = 1080; ///< --memory-size W H
    int memoryFrames = 8;                        ///< --memory-frames N (0 skips the measurement)
    bool memoryProbe = false;                    ///< --memory-probe: be that child process

    bool help = false;
};

/// Parses the command line. Throws InputError naming the option on anything it cannot use.
BenchOptions parseBenchOptions(int argc, const char* const* argv);

const char* benchOptionsHelp();

} // namespace pathlab::bench
