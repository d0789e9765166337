#include "map_files.h"

#include "pathlab/images/false_colour.h"
#include "pathlab/images/image_io.h"
#include "pathlab/images/scale_bar.h"

#include <algorithm>
#include <cctype>

namespace pathlab::viewer {

MapFormat mapFormatOf(const std::string& path) {
    const size_t dot = path.find_last_of('.');
    std::string ext = dot == std::string::npos ? "" : path.substr(dot);
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext == ".exr" ? MapFormat::Exr : ext == ".png" ? MapFormat::Png : MapFormat::Unknown;
}

std::string writeMapFile(const std::string& path, int width, int height,
                         const std::vector<float>& values, const std::string& what,
                         const std::optional<LogScale>& range) {
    if (mapFormatOf(path) != MapFormat::Png) {
        std::vector<float> rgb(3 * values.size());
        for (size_t i = 0; i < values.size(); ++i) std::fill_n(&rgb[3 * i], 3, values[i]);
        writeImage(path, width, height, rgb);
        return "wrote " + path + ": " + what;
    }
    const LogScale scale = range ? *range : decadeScale(values);
    std::vector<unsigned char> rgba;
    logScaleImage(values, scale, rgba);
    writeDisplayImage(path, width, height + scaleBarHeight(width),
                      withScaleBarBelow(rgba, width, height, scale));
    return "wrote " + path + ": " + what + ", log scale " + scaleLabel(scale.low) + " (black) to " +
           scaleLabel(scale.high) + " (red)" + (range ? " as --map-range set" : "") +
           ", grey: 0 or no value; scale bar beneath";
}

} // namespace pathlab::viewer
