// libpathlab_image_files.so: image files through OpenImageIO, loaded by image_io.cpp on first use.
#include "image_files.h"

#include <OpenImageIO/imageio.h>

namespace pathlab::plugin {

namespace {

std::string write(const std::string& path, int width, int height, const void* pixels, bool eightBit) {
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

std::string read(const std::string& path, FilePixels& pixels) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) return OIIO::geterror();
    const OIIO::ImageSpec& spec = in->spec();
    pixels.width = spec.width;
    pixels.height = spec.height;
    pixels.channels = spec.nchannels;
    pixels.integer = spec.format.basetype == OIIO::TypeDesc::UINT8 ||
                     spec.format.basetype == OIIO::TypeDesc::UINT16;
    pixels.values.resize(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.values.data()))
        return in->geterror();
    return "";
}

const ImageFiles files = {write, read};

} // namespace

} // namespace pathlab::plugin

extern "C" __attribute__((visibility("default"))) const pathlab::plugin::ImageFiles*
pathlab_image_files() {
    return &pathlab::plugin::files;
}
