#include "map_files.h"

#include "pathlab/false_colour.h"
#include "pathlab/image_io.h"
#include "pathlab/scale_bar.h"

#include <algorithm>
#include <cctype>

namespace pathlab::viewer {

namespace {

bool isPng(const std::string& path) {
    if (path.size() < 4) return false;
    std::string ext = path.substr(path.size() - 4);
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext == ".png";
}

} // namespace

std::string writeMapFile(const std::string& path, int width, int height,
                         const std::vector<float>& values, const std::string& what) {
    if (!isPng(path)) {
        std::vector<float> rgb(3 * values.size());
        for (size_t i = 0; i < values.size(); ++i) std::fill_n(&rgb[3 * i], 3, values[i]);
        writeImage(path, width, height, rgb);
        return "wrote " + path + ": " + what;
    }
    const LogScale scale = decadeScale(values);
    std::vector<unsigned char> rgba;
    logScaleImage(values, scale, rgba);
    writeDisplayImage(path, width, height + scaleBarHeight(width),
                      withScaleBarBelow(rgba, width, height, scale));
    return "wrote " + path + ": " + what + ", log scale " + scaleLabel(scale.low) + " (black) to " +
           scaleLabel(scale.high) + " (red), grey: 0 or no value; scale bar beneath";
}

} // namespace pathlab::viewer
