#pragma once
/// Everything the command line (and the .ecs files it names) can set.

#include "pathlab/camera.h"
#include "pathlab/lab_parameters.h"
#include "pathlab/lab_registry.h"
#include "pathlab/scene.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace pathlab {

struct RenderOptions {
    // Scene
    std::string sceneName;               ///< the .ecs or .obj named first, for reports
    std::vector<std::string> sceneScripts; ///< -c files read, those they include as well
    std::vector<std::string> objFiles;   ///< -i, resolved relative to the .ecs that named them
    std::vector<PointLight> pointLights; ///< --pointlight
    CameraSettings camera;
    bool cameraSet = false;              ///< any of --vp/--vi/--vu/--fov was given
    int width = 512, height = 512;       ///< --size

    // Estimator
    Lab lab = Lab::Branching;                        ///< --lab
    Implementation implementation = Implementation::Student; ///< --solution
    LabParameters parameters;                        ///< --max-depth, --continue-prob
    uint64_t seed = 0;                               ///< --seed
    int threads = 0;                                 ///< --threads; 0 = all cores

    // Headless output
    std::string outputImage;       ///< -o
    int spp = 16;                  ///< --spp
    std::string statsFile;         ///< --stats
    int seedCount = 1;             ///< --seeds: that many images, for seeds seed, seed+1, ...

    // Interactive window
    int sppPerFrame = 1;           ///< --spp-per-frame
    bool printFrameRate = false;   ///< --print-frame-rate
    int frames = 0;                ///< --frames: quit after this many (0 = run until closed)
    std::string screenshot;        ///< --screenshot: save after --frames, then quit
    std::string windowCapture;     ///< --capture-window: the window as shown, panel included
    std::string referenceImage;    ///< --reference: image for the difference view

    bool help = false;             ///< --help
};

/// Parses the command line; -c files are read in place, as if their tokens had been typed there.
/// Throws InputError naming the option (and file:line for .ecs files) on anything it cannot use.
RenderOptions parseRenderOptions(int argc, const char* const* argv);

/// The option summary printed by --help.
const char* renderOptionsHelp();

/// Loads the scene files the options name and adds their lights and camera.
Scene loadScene(const RenderOptions& options);

} // namespace pathlab
