#include "pathlab/image_io.h"

#include "pathlab/input_error.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <unistd.h>

namespace pathlab {

namespace {

namespace fs = std::filesystem;

std::string lowerExtension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext;
}

/// A name in the same folder (so the rename is atomic) with the same extension (so
/// OpenImageIO picks the same format), unique per process.
std::string temporaryNameFor(const std::string& path) {
    const fs::path p(path);
    const std::string name = "." + p.stem().string() + ".tmp" + std::to_string(::getpid()) +
                             p.extension().string();
    return (p.parent_path() / name).string();
}

void moveIntoPlace(const std::string& temporary, const std::string& path) {
    std::error_code error;
    fs::rename(temporary, path, error);
    if (error) {
        fs::remove(temporary, error);
        throw InputError(path + ": cannot move the finished image into place");
    }
}

/// Portable float map, written by hand only where OpenImageIO has no PFM writer (before 2.5 its
/// PNM plugin reads PFM but writes 8-bit P6). Little-endian floats (scale -1), rows bottom-up.
bool writePfm(const std::string& path, int width, int height, const std::vector<float>& rgb) {
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (!file) return false;
    std::fprintf(file, "PF\n%d %d\n-1.0\n", width, height);
    static_assert(sizeof(float) == 4, "PFM stores 32-bit floats");
    bool ok = true;
    for (int y = height - 1; y >= 0 && ok; --y)
        ok = std::fwrite(&rgb[3 * static_cast<size_t>(y) * width], sizeof(float),
                         3 * static_cast<size_t>(width), file) == 3 * static_cast<size_t>(width);
    return std::fclose(file) == 0 && ok;
}

} // namespace

float linearToSrgb(float linear) {
    const float v = std::clamp(linear, 0.0f, 1.0f);
    return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

void checkImageOutputPath(const std::string& path, const std::string& option) {
    const std::string ext = lowerExtension(path);
    if (ext != ".exr" && ext != ".pfm" && ext != ".png" && ext != ".hdr")
        throw InputError("option " + option + ": '" + path +
                         "' must end in .exr, .pfm, .hdr (linear radiance) or .png (sRGB)");
    fs::path folder = fs::path(path).parent_path();
    if (folder.empty()) folder = ".";
    std::error_code error;
    if (!fs::is_directory(folder, error))
        throw InputError("option " + option + ": folder '" + folder.string() + "' does not exist");
    if (::access(folder.c_str(), W_OK) != 0)
        throw InputError("option " + option + ": folder '" + folder.string() + "' is not writable");
    if (fs::is_directory(path, error))
        throw InputError("option " + option + ": '" + path + "' is a folder");
}

void writeImage(const std::string& path, int width, int height, const std::vector<float>& rgb) {
    checkImageOutputPath(path);
    const std::string temporary = temporaryNameFor(path);
    auto out = OIIO::ImageOutput::create(temporary);
    if (!out && lowerExtension(path) == ".pfm") {
        if (!writePfm(temporary, width, height, rgb)) {
            std::error_code ignored;
            fs::remove(temporary, ignored);
            throw InputError(path + ": cannot write the image");
        }
        moveIntoPlace(temporary, path);
        return;
    }
    if (!out) throw InputError(path + ": OpenImageIO cannot write this format");

    const bool png = lowerExtension(path) == ".png";
    OIIO::ImageSpec spec(width, height, 3, png ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
    spec.attribute("oiio:ColorSpace", png ? "sRGB" : "Linear");
    spec.attribute("Software", "PathLab");
    bool ok = out->open(temporary, spec);
    if (ok) {
        if (png) {
            std::vector<uint8_t> bytes(rgb.size());
            for (size_t i = 0; i < rgb.size(); ++i)
                bytes[i] = static_cast<uint8_t>(std::lround(255.0f * linearToSrgb(rgb[i])));
            ok = out->write_image(OIIO::TypeDesc::UINT8, bytes.data());
        } else {
            ok = out->write_image(OIIO::TypeDesc::FLOAT, rgb.data());
        }
        ok = out->close() && ok;
    }
    if (!ok) {
        const std::string why = out->geterror();
        std::error_code ignored;
        fs::remove(temporary, ignored);
        throw InputError(path + ": cannot write the image: " + why);
    }
    moveIntoPlace(temporary, path);
}

void writeDisplayImage(const std::string& path, int width, int height,
                       const std::vector<unsigned char>& rgb8) {
    checkImageOutputPath(path);
    const std::string temporary = temporaryNameFor(path);
    auto out = OIIO::ImageOutput::create(temporary);
    if (!out) throw InputError(path + ": OpenImageIO cannot write this format");
    OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:ColorSpace", "sRGB");
    bool ok = out->open(temporary, spec) && out->write_image(OIIO::TypeDesc::UINT8, rgb8.data());
    ok = out->close() && ok;
    if (!ok) {
        std::error_code ignored;
        fs::remove(temporary, ignored);
        throw InputError(path + ": cannot write the image: " + out->geterror());
    }
    moveIntoPlace(temporary, path);
}

Image readImage(const std::string& path) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw InputError(path + ": cannot read the image: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    Image image;
    image.width = spec.width;
    image.height = spec.height;
    const int channels = spec.nchannels;
    std::vector<float> pixels(static_cast<size_t>(spec.width) * spec.height * channels);
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data()))
        throw InputError(path + ": cannot read the image: " + in->geterror());
    const bool srgb = spec.format.basetype == OIIO::TypeDesc::UINT8 ||
                      spec.format.basetype == OIIO::TypeDesc::UINT16;
    image.rgb.resize(static_cast<size_t>(spec.width) * spec.height * 3);
    for (size_t i = 0; i < image.rgb.size() / 3; ++i) {
        for (int c = 0; c < 3; ++c) {
            float v = pixels[i * channels + std::min(c, channels - 1)];
            if (srgb) v = v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
            image.rgb[3 * i + c] = v;
        }
    }
    return image;
}

} // namespace pathlab
