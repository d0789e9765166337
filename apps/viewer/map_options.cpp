#include "map_options.h"

#include "map_files.h"
#include "window_options.h"

#include "pathlab/image_io.h"
#include "pathlab/input_error.h"

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
    };
}

void checkMapOptions(const MapOptions& maps, const RenderOptions& options,
                     const WindowOptions& window) {
    if (!maps.any()) return;
    const std::string first = maps.errorImages.empty() ? "--noise-image" : "--error-image";
    if (options.outputImage.empty())
        throw InputError("option " + first +
                         ": only with -o (a headless render); the window shows the maps with v");
    if (!maps.errorImages.empty() && window.referenceImage.empty())
        throw InputError("option --error-image: needs --reference FILE.exr, the image to compare "
                         "with");
    if (!maps.noiseImages.empty() && options.spp < 2)
        throw InputError("option --noise-image: needs --spp 2 or more (a pixel's variance needs "
                         "two samples)");
    for (const std::string& path : maps.errorImages) checkMapPath(path, "--error-image");
    for (const std::string& path : maps.noiseImages) checkMapPath(path, "--noise-image");
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
                         FILE.exr holds the values (in all three channels); FILE.png shows
                         them in false colour on a log scale, black low to red high, grey
                         where there is no value, with a scale bar beneath. Give an option
                         twice (a.exr and a.png) for both
)";
}

} // namespace pathlab::viewer
