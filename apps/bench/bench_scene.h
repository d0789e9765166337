#pragma once
/// The scenes the benchmark renders, as viewer-style arguments.

#include "pathlab/render/render_options.h"

#include <string>
#include <vector>

namespace pathlab::bench {

/// A scene to measure: its name and the arguments that load it (as the viewer takes them).
struct BenchScene {
    std::string name;
    std::string file;                   ///< the .ecs file it comes from
    std::vector<std::string> arguments; ///< e.g. {"-c", "models/cornell_box_VI2_Specular.ecs"}
};

/// The scene of an .ecs file, as it is.
BenchScene sceneFromFile(const std::string& ecsFile);

/// An Embree scene script turned into command-line arguments that PathLab's viewer and Embree's
/// pathtracer both read: file paths made absolute, and every point light's intensity scaled by
/// `lightScale` (Embree's cornell_box.ecs clips in 8 bits at full intensity).
BenchScene peerSceneFromFile(const std::string& ecsFile, float lightScale);

/// The render options of `scene` at the given size.
RenderOptions renderOptionsFor(const BenchScene& scene, int width, int height);

} // namespace pathlab::bench
