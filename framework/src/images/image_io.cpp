#include "pathlab/images/image_io.h"

#include "image_files.h"

#include "pathlab/support/input_error.h"
#include "pathlab/support/this_process.h"

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
            if (auto entry =
                    reinterpret_cast<Entry>(findLibrarySymbol(library, "pathlab_image_files", why)))
                return entry();
            errors += " " + why;
        }
        // An InputError, so that the viewer reports it (even from a key press) and exits with 2.
        throw InputError("cannot load the image-file plug-in " +
                         std::string(imagePluginFileName()) + " from " + program.string() +
                         " or the folder above:" +
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
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return std::tolower(c); });
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
    const std::string name =
        "." + p.stem().string() + ".tmp" + std::to_string(processId()) + p.extension().string();
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

/// Portable float map, read and written here without the plug-in: a program that only renders
/// to .pfm (the grader's renders) never loads OpenImageIO, whose loading (a few dozen libraries)
/// takes longer than a small render. Little-endian floats (scale -1), rows bottom-up.
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

/// The next whitespace-delimited word of a PFM header.
std::string headerWord(std::istream& in) {
    std::string word;
    in >> word;
    return word;
}

/// Reads a PFM (colour "PF" or grey "Pf", either byte order); throws InputError naming what is
/// wrong. The file may come from an untrusted process: every size is checked before use.
Image readPfm(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + ": cannot read the image: cannot open the file");
    const std::string magic = headerWord(in);
    const int channels = magic == "PF" ? 3 : magic == "Pf" ? 1 : 0;
    long long width = 0, height = 0;
    double scale = 0;
    if (channels == 0 || !(in >> width >> height >> scale) || width <= 0 || height <= 0 ||
        width > 65536 || height > 65536 || scale == 0)
        throw InputError(path + ": cannot read the image: not a PFM header (PF or Pf, width, "
                                "height, scale)");
    in.get(); // the single whitespace character that ends the header
    const size_t values = static_cast<size_t>(width) * static_cast<size_t>(height) * channels;
    // The pixels' size against the file's before any allocation: a header may claim anything.
    const std::streamoff header = in.tellg();
    in.seekg(0, std::ios::end);
    const std::streamoff fileSize = in.tellg();
    in.seekg(header);
    if (header < 0 || fileSize - header < static_cast<std::streamoff>(values * 4))
        throw InputError(path + ": cannot read the image: the file ends before its pixels do");
    std::vector<float> file(values);
    if (!in.read(reinterpret_cast<char*>(file.data()), static_cast<std::streamsize>(values * 4)))
        throw InputError(path + ": cannot read the image: the file ends before its pixels do");
    const bool bigEndianFile = scale > 0;
    const uint16_t probe = 1;
    const bool bigEndianHost = *reinterpret_cast<const uint8_t*>(&probe) == 0;
    if (bigEndianFile != bigEndianHost)
        for (float& v : file) {
            auto* bytes = reinterpret_cast<uint8_t*>(&v);
            std::reverse(bytes, bytes + 4);
        }
    Image image;
    image.width = static_cast<int>(width);
    image.height = static_cast<int>(height);
    image.rgb.resize(static_cast<size_t>(width) * static_cast<size_t>(height) * 3);
    for (long long y = 0; y < height; ++y) // rows bottom-up in the file
        for (long long x = 0; x < width; ++x)
            for (int c = 0; c < 3; ++c)
                image.rgb[3 * (static_cast<size_t>(y) * width + x) + c] =
                    file[channels * (static_cast<size_t>(height - 1 - y) * width + x) +
                         (channels == 3 ? c : 0)];
    return image;
}

/// Moves the temporary file written for `path` into place, or, when writing it failed (`why`),
/// removes it and says why: a failed write never leaves a half-written image behind.
void finishWrite(const std::string& temporary, const std::string& path, const std::string& why) {
    if (why == "unsupported") throw InputError(path + ": OpenImageIO cannot write this format");
    if (!why.empty()) {
        std::error_code ignored;
        fs::remove(temporary, ignored);
        throw InputError(path + ": cannot write the image: " + why);
    }
    moveIntoPlace(temporary, path);
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
    } else if (lowerExtension(path) == ".pfm") {
        why = writePfm(temporary, width, height, rgb) ? "" : "cannot write the file";
    } else {
        why = writeThroughPlugin(temporary, width, height, rgb.data(), false);
    }
    finishWrite(temporary, path, why);
}

void writeDisplayImage(const std::string& path, int width, int height,
                       const std::vector<unsigned char>& rgb8) {
    checkImageOutputPath(path);
    const std::string temporary = temporaryNameFor(path);
    const std::string why = writeThroughPlugin(temporary, width, height, rgb8.data(), true);
    finishWrite(temporary, path, why);
}

Image readImage(const std::string& path) {
    if (lowerExtension(path) == ".pfm") return readPfm(path);
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
            if (pixels.integer)
                v = v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
            image.rgb[3 * i + c] = v;
        }
    }
    return image;
}

const char* imagePluginFileName() { return PATHLAB_IMAGE_PLUGIN_FILE; }

} // namespace pathlab
