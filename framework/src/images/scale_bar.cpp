#include "pathlab/images/scale_bar.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pathlab {

namespace {

/// The strip's rows, top to bottom: a gap, the bar, a gap, the labels, a gap.
constexpr int gapRows = 3, barRows = 8;

/// The digits the labels use, 3 × 5 pixels each, one row of three bits per entry (bit 2 left).
const unsigned char* glyph(char c) {
    static const unsigned char digits[10][5] = {
        {7, 5, 5, 5, 7}, {2, 6, 2, 2, 7}, {7, 1, 7, 4, 7}, {7, 1, 7, 1, 7}, {5, 5, 7, 1, 1},
        {7, 4, 7, 1, 7}, {7, 4, 7, 5, 7}, {7, 1, 1, 1, 1}, {7, 5, 7, 5, 7}, {7, 5, 7, 1, 7}};
    static const unsigned char point[5] = {0, 0, 0, 0, 2}, minus[5] = {0, 0, 7, 0, 0},
                               plus[5] = {0, 2, 7, 2, 0}, e[5] = {2, 5, 7, 4, 3},
                               blank[5] = {0, 0, 0, 0, 0};
    if (c >= '0' && c <= '9') return digits[c - '0'];
    switch (c) {
    case '.': return point;
    case '-': return minus;
    case '+': return plus;
    case 'e': return e;
    default: return blank;
    }
}

/// Pixels per glyph pixel: 2 where the labels fit, 1 on a narrow map.
int glyphScale(int width) { return width >= 160 ? 2 : 1; }

/// Writes `text` in white with its left edge at `x0`, its top at `y0`, clipped to the image.
void drawText(std::vector<unsigned char>& rgb, int width, int height, int x0, int y0,
              const std::string& text, int scale) {
    for (size_t k = 0; k < text.size(); ++k) {
        const unsigned char* rows = glyph(text[k]);
        for (int gy = 0; gy < 5 * scale; ++gy)
            for (int gx = 0; gx < 3 * scale; ++gx) {
                if (!(rows[gy / scale] & (4 >> (gx / scale)))) continue;
                const int x = x0 + static_cast<int>(k) * 4 * scale + gx, y = y0 + gy;
                if (x < 0 || x >= width || y < 0 || y >= height) continue;
                std::fill_n(&rgb[3 * (static_cast<size_t>(y) * width + x)], 3, 255);
            }
    }
}

} // namespace

int scaleBarHeight(int width) { return 3 * gapRows + barRows + 5 * glyphScale(width); }

std::string scaleLabel(float value) {
    char text[32];
    const float decade = std::log10(value);
    if (std::fabs(decade - std::round(decade)) < 1e-4f && std::fabs(decade) > 3.5f)
        std::snprintf(text, sizeof text, "1e%d", static_cast<int>(std::round(decade)));
    else
        std::snprintf(text, sizeof text, "%.4g", value);
    return text;
}

std::vector<unsigned char> withScaleBarBelow(const std::vector<unsigned char>& rgba, int width,
                                             int height, const LogScale& scale) {
    const int total = height + scaleBarHeight(width);
    std::vector<unsigned char> rgb(3 * static_cast<size_t>(width) * total, 0);
    for (size_t i = 0; i < static_cast<size_t>(width) * height; ++i)
        std::copy_n(&rgba[4 * i], 3, &rgb[3 * i]);
    // Column x shows the value at its centre, on the same logarithmic axis as the map.
    const int barTop = height + gapRows;
    for (int x = 0; x < width; ++x) {
        unsigned char colour[4];
        heatColour((static_cast<float>(x) + 0.5f) / static_cast<float>(width), colour);
        for (int y = barTop; y < barTop + barRows; ++y)
            std::copy_n(colour, 3, &rgb[3 * (static_cast<size_t>(y) * width + x)]);
    }
    const int s = glyphScale(width), labelTop = barTop + barRows + gapRows;
    const std::string high = scaleLabel(scale.high);
    drawText(rgb, width, total, 0, labelTop, scaleLabel(scale.low), s);
    drawText(rgb, width, total, width - static_cast<int>(high.size()) * 4 * s + s, labelTop, high,
             s);
    return rgb;
}

} // namespace pathlab
