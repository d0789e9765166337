#include "reports/tile_z_map.h"

#include "pathlab/images/false_colour.h"

#include <cmath>

namespace pathlab::grader {

double zScoreOfP(double p, double t) {
    if (std::isnan(p) || std::isnan(t)) return NAN;
    // erfc(z / √2) is the two-sided tail of z: bisection finds the z whose tail is p, far
    // enough (to 1e-9) for a colour; p = 0 (a region that cannot be noise) saturates.
    double low = 0, high = 40;
    for (int i = 0; i < 64; ++i) {
        const double mid = (low + high) / 2;
        (std::erfc(mid / std::sqrt(2.0)) > p ? low : high) = mid;
    }
    return std::copysign((low + high) / 2, t);
}

double tileZ(const std::vector<double>& regionT, const std::vector<double>& regionP, int tile) {
    const size_t first = 3 * static_cast<size_t>(tile + 1);
    size_t smallest = first;
    for (size_t i = first + 1; i < first + 3; ++i)
        if (regionP[i] < regionP[smallest]) smallest = i;
    return zScoreOfP(regionP[smallest], regionT[smallest]);
}

std::vector<unsigned char> tileZImage(const std::vector<double>& regionT,
                                      const std::vector<double>& regionP, int tilesPerSide,
                                      int width, int height) {
    const size_t tiles = static_cast<size_t>(tilesPerSide) * tilesPerSide;
    if (tilesPerSide <= 0 || regionT.size() != 3 * (1 + tiles) || regionP.size() != regionT.size())
        return {};
    std::vector<unsigned char> colours(4 * tiles);
    for (size_t tile = 0; tile < tiles; ++tile) {
        const double z = tileZ(regionT, regionP, static_cast<int>(tile));
        if (std::isnan(z)) {
            colours[4 * tile] = colours[4 * tile + 1] = colours[4 * tile + 2] = undefinedGrey;
            continue;
        }
        divergingColour(static_cast<float>(z / tileZSaturation), &colours[4 * tile]);
    }
    std::vector<unsigned char> rgb(3 * static_cast<size_t>(width) * height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            // The tile regionMeans (isolation/render_run.h) puts the pixel in.
            const int tile = (y * tilesPerSide / height) * tilesPerSide + x * tilesPerSide / width;
            for (int c = 0; c < 3; ++c)
                rgb[3 * (static_cast<size_t>(y) * width + x) + c] = colours[4 * tile + c];
        }
    return rgb;
}

std::string tileZLegendHtml() {
    const std::string saturation = std::to_string(static_cast<int>(tileZSaturation));
    return "<p class=\"legend\"><span style=\"display:inline-block;width:192px;height:12px;"
           "vertical-align:middle;border:1px solid #888;background:linear-gradient(to right,"
           "#0000ff,#ffffff,#ff0000)\"></span> tile z-score: −" +
           saturation + " and below (too dark), 0 white, +" + saturation +
           " and above (too bright); grey: none</p>\n";
}

} // namespace pathlab::grader
