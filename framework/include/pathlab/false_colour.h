#pragma once
/// Relative differences as false colour, for the viewer's difference view.

#include <vector>

namespace pathlab {

/// Per pixel |a − b| / max(b, 0.01) (channel average), mapped black→blue→green→yellow→red over
/// [0, scale]; RGBA8 out. Returns the median relative difference.
float relativeDifferenceImage(const std::vector<float>& a, const std::vector<float>& b, float scale,
                              std::vector<unsigned char>& rgba);

/// Linear RGB floats to sRGB RGBA8 for display.
void toDisplay(const std::vector<float>& rgb, std::vector<unsigned char>& rgba);

} // namespace pathlab
