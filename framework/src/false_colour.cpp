#include "pathlab/false_colour.h"

#include "pathlab/image_io.h"

#include <algorithm>
#include <cmath>

namespace pathlab {

namespace {
void heat(float t, unsigned char* out) {
    // Four segments: black→blue→green→yellow→red.
    static const float stops[5][3] = {{0, 0, 0}, {0, 0, 1}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}};
    t = std::clamp(t, 0.0f, 1.0f) * 4.0f;
    const int i = std::min(static_cast<int>(t), 3);
    const float f = t - static_cast<float>(i);
    for (int c = 0; c < 3; ++c)
        out[c] = static_cast<unsigned char>(255.0f * (stops[i][c] * (1 - f) + stops[i + 1][c] * f));
    out[3] = 255;
}
} // namespace

float relativeDifferenceImage(const std::vector<float>& a, const std::vector<float>& b, float scale,
                              std::vector<unsigned char>& rgba) {
    const size_t pixels = std::min(a.size(), b.size()) / 3;
    rgba.assign(4 * pixels, 0);
    std::vector<float> differences(pixels);
    for (size_t i = 0; i < pixels; ++i) {
        float d = 0;
        for (int c = 0; c < 3; ++c)
            d += std::fabs(a[3 * i + c] - b[3 * i + c]) / std::max(b[3 * i + c], 0.01f);
        differences[i] = d / 3;
        heat(differences[i] / scale, &rgba[4 * i]);
    }
    if (pixels == 0) return 0;
    std::nth_element(differences.begin(), differences.begin() + pixels / 2, differences.end());
    return differences[pixels / 2];
}

void toDisplay(const std::vector<float>& rgb, std::vector<unsigned char>& rgba) {
    const size_t pixels = rgb.size() / 3;
    rgba.resize(4 * pixels);
    for (size_t i = 0; i < pixels; ++i) {
        for (int c = 0; c < 3; ++c)
            rgba[4 * i + c] =
                static_cast<unsigned char>(std::lround(255.0f * linearToSrgb(rgb[3 * i + c])));
        rgba[4 * i + 3] = 255;
    }
}

} // namespace pathlab
