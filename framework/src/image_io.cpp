#include "pathlab/image_io.h"

#include "image_files.h"

#include "pathlab/input_error.h"
#include "pathlab/this_process.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace pathlab {

namespace {

namespace fs = std::filesystem;

/// The image-file plug-in (image_files.h), loaded on first use from beside this program (or
/// from the folder above: the tests live one level below it).
const plugin::ImageFiles& imageFiles() {
    static const plugin::ImageFiles* files = [] {
        const fs::path program = thisProgram().parent_path();
        std::string errors;
        for (const fs::path& folder : {program, program.parent_path()}) {
            const fs::path library = folder / imagePluginFileName();
            if (!fs::exists(library)) continue;
            std::string why;
            using Entry = const plugin::ImageFiles* (*)();
            if (auto entry = reinterpret_cast<Entry>(findLibrarySymbol(library, "pathlab_image_files", why)))
                return entry();
            errors += " " + why;
        }
        // An InputError, so that the viewer reports it (even from a key press) and exits with 2.
        throw InputError("cannot load the image-file plug-in " + std::string(imagePluginFileName()) +
                         " from " + program.string() + " or the folder above:" +
                         (errors.empty() ? " not there (rebuild: make build)" : errors));
    }();
    return *files;
}

/// The plug-in's write, "" when it succeeded.
std::string writeThroughPlugin(const std::string& path, int width, int height, const void* pixels,
                               bool eightBit) {
    const char* why = imageFiles().write(path.c_str(), width, height, pixels, eightBit);
    return why ? why : "";
}

std::string lowerExtension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext;
}

/// Whether a file can be made in `folder`: tried, since permission bits, ACLs, read-only mounts
/// and Windows each answer the question differently.
bool canWriteIn(const fs::path& folder) {
    const fs::path probe = folder / (".pathlab-write-test-" + std::to_string(processId()));
    const bool written = static_cast<bool>(std::ofstream(probe));
    std::error_code ignored;
    fs::remove(probe, ignored);
    return written;
}

/// A name in the same folder (so the rename is atomic) with the same extension (so
/// OpenImageIO picks the same format), unique per process.
std::string temporaryNameFor(const std::string& path) {
    const fs::path p(path);
    const std::string name = "." + p.stem().string() + ".tmp" + std::to_string(processId()) +
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
    if (!canWriteIn(folder))
        throw InputError("option " + option + ": folder '" + folder.string() + "' is not writable");
    if (fs::is_directory(path, error))
        throw InputError("option " + option + ": '" + path + "' is a folder");
}

void writeImage(const std::string& path, int width, int height, const std::vector<float>& rgb) {
    checkImageOutputPath(path);
    const std::string temporary = temporaryNameFor(path);
    const bool png = lowerExtension(path) == ".png";
    std::string why;
    if (png) {
        std::vector<uint8_t> bytes(rgb.size());
        for (size_t i = 0; i < rgb.size(); ++i)
            bytes[i] = static_cast<uint8_t>(std::lround(255.0f * linearToSrgb(rgb[i])));
        why = writeThroughPlugin(temporary, width, height, bytes.data(), true);
    } else {
        why = writeThroughPlugin(temporary, width, height, rgb.data(), false);
        if (why == "unsupported" && lowerExtension(path) == ".pfm")
            why = writePfm(temporary, width, height, rgb) ? "" : "cannot write the file";
    }
    if (why == "unsupported") throw InputError(path + ": OpenImageIO cannot write this format");
    if (!why.empty()) {
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
    const std::string why = writeThroughPlugin(temporary, width, height, rgb8.data(), true);
    if (why == "unsupported") throw InputError(path + ": OpenImageIO cannot write this format");
    if (!why.empty()) {
        std::error_code ignored;
        fs::remove(temporary, ignored);
        throw InputError(path + ": cannot write the image: " + why);
    }
    moveIntoPlace(temporary, path);
}

Image readImage(const std::string& path) {
    plugin::FilePixels pixels;
    if (const char* why = imageFiles().read(path.c_str(), &pixels))
        throw InputError(path + ": cannot read the image: " + why);
    Image image;
    image.width = pixels.width;
    image.height = pixels.height;
    const int channels = pixels.channels;
    image.rgb.resize(static_cast<size_t>(pixels.width) * pixels.height * 3);
    for (size_t i = 0; i < image.rgb.size() / 3; ++i) {
        for (int c = 0; c < 3; ++c) {
            float v = pixels.values[i * channels + std::min(c, channels - 1)];
            if (pixels.integer) v = v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
            image.rgb[3 * i + c] = v;
        }
    }
    return image;
}

const char* imagePluginFileName() { return PATHLAB_IMAGE_PLUGIN_FILE; }

} // namespace pathlab
