#pragma once
// The image-file plug-in's interface (framework internal). OpenImageIO, with the 260 or so
// libraries Debian builds it with, costs a process about 120 MB and 0.17 s just to load, so it
// lives in a shared library of its own, libpathlab_image_files.so, that image_io.cpp loads when
// a first image is read or written: the window renders without it until a screenshot.

#include <string>
#include <vector>

namespace pathlab::plugin {

/// Pixels as a file holds them, before any colour conversion.
struct FilePixels {
    int width = 0, height = 0, channels = 0;
    bool integer = false;      ///< 8- or 16-bit values: sRGB-encoded by convention
    std::vector<float> values; ///< channels per pixel, top row first
};

struct ImageFiles {
    /// Writes 3-channel pixels, 8-bit (`eightBit`, sRGB) or float (linear) as `path`'s extension
    /// says. Returns "" when written, "unsupported" when no writer knows the format, else why not.
    std::string (*write)(const std::string& path, int width, int height, const void* pixels,
                         bool eightBit);
    /// Reads a file; returns "" or why not.
    std::string (*read)(const std::string& path, FilePixels& pixels);
};

} // namespace pathlab::plugin

/// The plug-in's one export.
extern "C" const pathlab::plugin::ImageFiles* pathlab_image_files();
