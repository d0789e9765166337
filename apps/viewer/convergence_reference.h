#pragma once
/// The image the convergence plot measures against: --reference when given, otherwise the one
/// `make reference` caches beside the viewer for the scene and the window's size; or, when
/// there is none, how to make one.

#include "pathlab/images/image_io.h"
#include "pathlab/render/render_options.h"

#include <filesystem>
#include <string>

namespace pathlab::viewer {

struct ConvergenceReference {
    Image image;         ///< empty (0 × 0) when there is none of this size
    std::string file;    ///< where it was read from
    std::string missing; ///< when empty: why, and the command that makes one
};

/// Where `make reference` (scripts/make-reference.sh) puts the reference of `scene` at
/// `width` × `height`: references/SCENE.WIDTHxHEIGHT.exr beside the viewer, i.e. in the build
/// folder.
std::filesystem::path cachedReferencePath(const std::string& scene, int width, int height);

/// The reference for a window of `width` × `height` on the options' scene: `referenceFile` (the
/// window's --reference, already read as `given`) when it is that size, else the cached one.
ConvergenceReference findConvergenceReference(const RenderOptions& options,
                                              const std::string& referenceFile, const Image& given,
                                              int width, int height);

/// One line for the panel: how to make a reference of this scene and size.
std::string howToMakeReference(const RenderOptions& options, int width, int height);

} // namespace pathlab::viewer
