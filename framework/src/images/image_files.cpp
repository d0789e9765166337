// The image-file plug-in (libpathlab_image_files.so on Linux): image files through OpenImageIO,
// loaded by image_io.cpp on first use.
#include "image_files.h"

#include "pathlab/support/this_process.h"

#include <OpenImageIO/imageio.h>

#include <string>
#include <vector>

namespace pathlab::plugin {

namespace {

/// What the last call on this thread answered: the interface hands out pointers into these.
thread_local std::string lastProblem;
thread_local std::vector<float> lastValues;

const char* answer(const std::string& problem) {
    if (problem.empty()) return nullptr;
    lastProblem = problem;
    return lastProblem.c_str();
}

std::string writeFile(const std::string& path, int width, int height, const void* pixels,
                      bool eightBit) {
    auto out = OIIO::ImageOutput::create(path);
    if (!out) return "unsupported";
    const OIIO::TypeDesc type = eightBit ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT;
    OIIO::ImageSpec spec(width, height, 3, type);
    spec.attribute("oiio:ColorSpace", eightBit ? "sRGB" : "Linear");
    spec.attribute("Software", "PathLab");
    bool ok = out->open(path, spec) && out->write_image(type, pixels);
    ok = out->close() && ok;
    return ok ? "" : out->geterror().empty() ? "the writer failed" : out->geterror();
}

std::string readFile(const std::string& path, FilePixels& pixels) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) return OIIO::geterror();
    const OIIO::ImageSpec& spec = in->spec();
    pixels.width = spec.width;
    pixels.height = spec.height;
    pixels.channels = spec.nchannels;
    pixels.integer = spec.format.basetype == OIIO::TypeDesc::UINT8 ||
                     spec.format.basetype == OIIO::TypeDesc::UINT16;
    lastValues.resize(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, lastValues.data()))
        return in->geterror();
    pixels.values = lastValues.data();
    return "";
}

const char* write(const char* path, int width, int height, const void* pixels, bool eightBit) {
    return answer(writeFile(path, width, height, pixels, eightBit));
}

const char* read(const char* path, FilePixels* pixels) { return answer(readFile(path, *pixels)); }

const ImageFiles files = {write, read};

} // namespace

} // namespace pathlab::plugin

extern "C" PATHLAB_EXPORT const pathlab::plugin::ImageFiles* pathlab_image_files() {
    return &pathlab::plugin::files;
}
