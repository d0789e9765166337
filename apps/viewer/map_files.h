#pragma once
/// A per-pixel map as a file: its values in an EXR, or false colour with a scale bar in a PNG.

#include "pathlab/images/false_colour.h"

#include <optional>
#include <string>
#include <vector>

namespace pathlab::viewer {

/// What a map file holds, by its extension (any case): the values, false colour, or neither.
enum class MapFormat { Exr, Png, Unknown };
MapFormat mapFormatOf(const std::string& path);

/// Writes `values` (one per pixel, `width` × `height`) to `path`: .exr the values in all three
/// channels; .png on `range`'s log scale, or decadeScale's where none is given
/// (pathlab/images/false_colour.h), with the scale bar beneath (pathlab/images/scale_bar.h).
/// Returns the line viewer -o prints for it, naming `what` the map shows and, for a PNG, its scale.
std::string writeMapFile(const std::string& path, int width, int height,
                         const std::vector<float>& values, const std::string& what,
                         const std::optional<LogScale>& range = std::nullopt);

} // namespace pathlab::viewer
