#pragma once
/// A false-coloured map with its scale beneath it, so that a PNG of it can be read alone.

#include "pathlab/images/false_colour.h"

#include <string>
#include <vector>

namespace pathlab {

/// The height in pixels of the strip scaleBarBelow adds under a map `width` pixels wide.
int scaleBarHeight(int width);

/// `rgba` (a `width` × `height` map coloured on `scale`) with a strip added beneath: a gap of
/// black, the palette from left (scale.low) to right (scale.high), every column the colour of
/// its value, and the two ends' values written under it in small digits. RGB8 out (3 bytes per
/// pixel), `width` × (height + scaleBarHeight(width)), ready for writeDisplayImage.
std::vector<unsigned char> withScaleBarBelow(const std::vector<unsigned char>& rgba, int width,
                                             int height, const LogScale& scale);

/// A scale end as the bar writes it: "0.01", "1", "1000", "1e-05".
std::string scaleLabel(float value);

} // namespace pathlab
