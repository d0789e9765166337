#pragma once
/// Values as false colour: the viewer's difference, noise and efficiency views, the maps
/// viewer -o writes, and the grader's tile z-scores.

#include <vector>

namespace pathlab {

/// Per pixel |a − b| / max(b, 0.01) (channel average), mapped black→blue→green→yellow→red over
/// [0, scale]; RGBA8 out. Returns the median relative difference.
float relativeDifferenceImage(const std::vector<float>& a, const std::vector<float>& b, float scale,
                              std::vector<unsigned char>& rgba);

/// The heat palette at t in [0, 1] (clamped): black→blue→green→yellow→red, into RGBA8 `out`.
void heatColour(float t, unsigned char* out);

/// The colour of a value without one (a noiseless pixel has no relative error to show): grey,
/// which the heat palette never takes.
constexpr unsigned char undefinedGrey = 128;

/// The range a map's colours span, on a logarithmic axis: `low` is black, `high` red, the
/// palette's stops a quarter of the decades apart. The maps' values (relative errors,
/// efficiencies) spread over decades, where a linear axis would show one bright pixel and black.
struct LogScale {
    float low = 0.01f, high = 1.0f;
    /// Where `value` sits on the palette, 0 to 1 (clamped).
    float position(float value) const;
};

/// The scale for `values`: the decade at or below their 2nd percentile to the decade at or above
/// their 98th, over the positive values alone (0 means undefined), at least one decade wide, so
/// that the scale bar's ends read as round numbers and a few outliers do not squeeze the rest.
LogScale decadeScale(const std::vector<float>& values);

/// Each value's heat colour on `scale` into RGBA8, one per value; 0 or not finite as
/// undefinedGrey.
void logScaleImage(const std::vector<float>& values, const LogScale& scale,
                   std::vector<unsigned char>& rgba);

/// A signed value on a diverging palette: blue for −1, white for 0, red for +1 (clamped), RGBA8.
void divergingColour(float t, unsigned char* out);

/// Linear RGB floats to sRGB RGBA8 for display.
void toDisplay(const std::vector<float>& rgb, std::vector<unsigned char>& rgba);

} // namespace pathlab
