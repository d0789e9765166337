#pragma once
/// The maps a headless render writes beside its image: --error-image (against --reference),
/// --noise-image and --efficiency-image, on their own scale or on --map-range's.

#include "pathlab/images/false_colour.h"
#include "pathlab/render/render_options.h"

#include <optional>
#include <string>
#include <vector>

namespace pathlab::viewer {

struct WindowOptions;

struct MapOptions {
    /// --error-image, once per file: each pixel's relative squared error against --reference.
    std::vector<std::string> errorImages;
    /// --noise-image, once per file: each pixel's relative standard error.
    std::vector<std::string> noiseImages;
    /// --efficiency-image, once per file: each pixel's efficiency (pixel_efficiency_map.h).
    std::vector<std::string> efficiencyImages;
    /// --map-range LO HI: the PNGs' log scale, the same for every map and render (two renders'
    /// maps compared by colour), in place of each map's own decades.
    std::optional<LogScale> range;

    bool any() const {
        return !errorImages.empty() || !noiseImages.empty() || !efficiencyImages.empty();
    }
};

/// The readers of the map options, into `maps`, for parseRenderOptions.
ExtraOptions mapOptionReaders(MapOptions& maps);

/// Throws InputError, naming the option, for maps that cannot be made: without -o, an error map
/// without --reference, a noise or efficiency map of fewer than 2 spp (no variance yet), a file
/// that is neither .exr nor .png or whose folder cannot be written, --map-range without a map.
/// Called before anything is rendered or written.
void checkMapOptions(const MapOptions& maps, const RenderOptions& options,
                     const WindowOptions& window);

/// The summary of the map options, for --help.
const char* mapOptionsHelp();

} // namespace pathlab::viewer
