#include "pathlab/images/false_colour.h"

#include "pathlab/images/image_io.h"

#include <algorithm>
#include <cmath>

namespace pathlab {

void heatColour(float t, unsigned char* out) {
    // Four segments: black→blue→green→yellow→red.
    static const float stops[5][3] = {{0, 0, 0}, {0, 0, 1}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}};
    t = std::clamp(t, 0.0f, 1.0f) * 4.0f;
    const int i = std::min(static_cast<int>(t), 3);
    const float f = t - static_cast<float>(i);
    for (int c = 0; c < 3; ++c)
        out[c] = static_cast<unsigned char>(255.0f * (stops[i][c] * (1 - f) + stops[i + 1][c] * f));
    out[3] = 255;
}

float LogScale::position(float value) const {
    const float decades = std::log10(high / low);
    return std::clamp(std::log10(value / low) / decades, 0.0f, 1.0f);
}

LogScale decadeScale(const std::vector<float>& values) {
    std::vector<float> positive;
    for (float v : values)
        if (v > 0 && std::isfinite(v)) positive.push_back(v);
    if (positive.empty()) return LogScale{};
    const auto percentile = [&](size_t percent) {
        const size_t k = std::min(positive.size() - 1, positive.size() * percent / 100);
        std::nth_element(positive.begin(), positive.begin() + static_cast<long>(k), positive.end());
        return positive[k];
    };
    const float lowDecade = std::floor(std::log10(percentile(2)));
    float highDecade = std::ceil(std::log10(percentile(98)));
    if (highDecade <= lowDecade) highDecade = lowDecade + 1;
    return {std::pow(10.0f, lowDecade), std::pow(10.0f, highDecade)};
}

void logScaleImage(const std::vector<float>& values, const LogScale& scale,
                   std::vector<unsigned char>& rgba) {
    rgba.resize(4 * values.size());
    for (size_t i = 0; i < values.size(); ++i) {
        unsigned char* out = &rgba[4 * i];
        if (values[i] > 0 && std::isfinite(values[i])) {
            heatColour(scale.position(values[i]), out);
        } else {
            out[0] = out[1] = out[2] = undefinedGrey;
            out[3] = 255;
        }
    }
}

void divergingColour(float t, unsigned char* out) {
    t = std::clamp(t, -1.0f, 1.0f);
    // White fades to pure red or blue: the tiles a test accepts stay pale, those it rejects not.
    const float fade = 1 - std::fabs(t);
    const float r = t > 0 ? 1 : fade, b = t < 0 ? 1 : fade;
    out[0] = static_cast<unsigned char>(std::lround(255 * r));
    out[1] = static_cast<unsigned char>(std::lround(255 * fade));
    out[2] = static_cast<unsigned char>(std::lround(255 * b));
    out[3] = 255;
}

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
        heatColour(differences[i] / scale, &rgba[4 * i]);
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
