#include "map_options.h"

#include "map_files.h"
#include "window_options.h"

#include "pathlab/images/image_io.h"
#include "pathlab/support/input_error.h"

#include <cmath>
#include <string>
#include <utility>

namespace pathlab::viewer {

namespace {

/// A map is values, not radiance: .exr keeps them, .png shows them in false colour; .pfm and
/// .hdr would pass for images.
void checkMapPath(const std::string& path, const std::string& option) {
    if (mapFormatOf(path) == MapFormat::Unknown)
        throw InputError("option " + option + ": '" + path +
                         "' must end in .exr (the values) or .png (false colour with a scale "
                         "bar); give the option twice for both");
    checkImageOutputPath(path, option);
}

} // namespace

ExtraOptions mapOptionReaders(MapOptions& maps) {
    return {
        {"error-image",
         [&maps](OptionReader& in, const Token& t) {
             maps.errorImages.push_back(in.value(t, "an .exr or .png file name").text);
         }},
        {"noise-image",
         [&maps](OptionReader& in, const Token& t) {
             maps.noiseImages.push_back(in.value(t, "an .exr or .png file name").text);
         }},
        {"efficiency-image",
         [&maps](OptionReader& in, const Token& t) {
             maps.efficiencyImages.push_back(in.value(t, "an .exr or .png file name").text);
         }},
        {"map-range",
         [&maps](OptionReader& in, const Token& t) {
             const float low = in.number(t, "the scale's low end, a positive number");
             const float high = in.number(t, "the scale's high end, a positive number");
             if (!(low > 0) || !(high > low) || !std::isfinite(high))
                 OptionReader::fail(t, "option --map-range expects LO HI with 0 < LO < HI (the "
                                       "ends of a log scale)");
             maps.range = LogScale{low, high};
         }},
    };
}

void checkMapOptions(const MapOptions& maps, const RenderOptions& options,
                     const WindowOptions& window) {
    if (!maps.any()) {
        if (maps.range)
            throw InputError("option --map-range: only with a map to draw (--error-image, "
                             "--noise-image or --efficiency-image, as .png)");
        return;
    }
    const std::string first = !maps.errorImages.empty()   ? "--error-image"
                              : !maps.noiseImages.empty() ? "--noise-image"
                                                          : "--efficiency-image";
    if (options.outputImage.empty())
        throw InputError("option " + first +
                         ": only with -o (a headless render); the window shows the maps with v");
    if (!maps.errorImages.empty() && window.referenceImage.empty())
        throw InputError("option --error-image: needs --reference FILE.exr, the image to compare "
                         "with");
    for (const auto& [option, files] : {std::pair{"--noise-image", &maps.noiseImages},
                                        std::pair{"--efficiency-image", &maps.efficiencyImages}})
        if (!files->empty() && options.spp < 2)
            throw InputError("option " + std::string(option) +
                             ": needs --spp 2 or more (a pixel's variance needs two samples)");
    for (const std::string& path : maps.errorImages) checkMapPath(path, "--error-image");
    for (const std::string& path : maps.noiseImages) checkMapPath(path, "--noise-image");
    for (const std::string& path : maps.efficiencyImages) checkMapPath(path, "--efficiency-image");
}

const char* mapOptionsHelp() {
    return R"(maps (with -o)
  --reference FILE.exr   also print relMSE (mean of (x-r)^2/(r^2+0.01) over pixels and
                         channels) and the relative RMSE (RMSE / mean of FILE) against
                         FILE, which must be the render's size; --stats adds "reference"
  --error-image FILE     each pixel's relative squared error against --reference (the
                         channels' mean of (x-r)^2/(r^2+0.01))
  --noise-image FILE     each pixel's relative standard error, from its own samples:
                         sqrt(variance/spp / (mean^2+0.01)), channels averaged (--spp 2+)
  --efficiency-image FILE
                         each pixel's efficiency, 1/(relative variance x CPU-seconds per
                         sample), the panel's efficiency pixel by pixel (--spp 2+)
                         FILE.exr holds the values (in all three channels); FILE.png shows
                         them in false colour on a log scale, black low to red high, grey
                         where there is no value, with a scale bar beneath. Give an option
                         twice (a.exr and a.png) for both
  --map-range LO HI      the PNGs' log scale from LO (black) to HI (red), the same for every
                         render, so that two renders' maps compare by colour (default: each
                         map's own decades, from its 2nd to its 98th percentile)
)";
}

} // namespace pathlab::viewer
