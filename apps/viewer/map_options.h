#pragma once
/// The maps a headless render writes beside its image: --error-image (against --reference) and
/// --noise-image.

#include "pathlab/render_options.h"

#include <string>
#include <vector>

namespace pathlab::viewer {

struct WindowOptions;

struct MapOptions {
    /// --error-image, once per file: each pixel's relative squared error against --reference.
    std::vector<std::string> errorImages;
    /// --noise-image, once per file: each pixel's relative standard error.
    std::vector<std::string> noiseImages;

    bool any() const { return !errorImages.empty() || !noiseImages.empty(); }
};

/// The readers of the map options, into `maps`, for parseRenderOptions.
ExtraOptions mapOptionReaders(MapOptions& maps);

/// Throws InputError, naming the option, for maps that cannot be made: without -o, an error map
/// without --reference, a noise map of fewer than 2 spp (no variance yet), a file that is neither
/// .exr nor .png or whose folder cannot be written. Called before anything is rendered or written.
void checkMapOptions(const MapOptions& maps, const RenderOptions& options,
                     const WindowOptions& window);

/// The summary of the map options, for --help.
const char* mapOptionsHelp();

} // namespace pathlab::viewer
