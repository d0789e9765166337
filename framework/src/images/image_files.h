#pragma once
// The image-file plug-in's interface (framework internal). OpenImageIO, with the 260 or so
// libraries Debian builds it with, costs a process about 120 MB and 0.17 s just to load, so it
// lives in a shared library of its own, libpathlab_image_files.so, that image_io.cpp loads when
// a first image is read or written: the window renders without it until a screenshot.
//
// Only C types cross this interface, so the plug-in may be built against another C++ standard
// library than the programs: the one OpenImageIO was built with (libstdc++ on Debian, where the
// clang + libc++ build of the kit still reads and writes images), or another runtime on Windows.

namespace pathlab::plugin {

/// Pixels as a file holds them, before any colour conversion.
struct FilePixels {
    int width = 0, height = 0, channels = 0;
    bool integer = false;          ///< 8- or 16-bit values: sRGB-encoded by convention
    const float* values = nullptr; ///< channels per pixel, top row first; the plug-in's memory,
                                   ///< valid until this thread's next call
};

/// Each function returns nullptr when it succeeded, else why not (the plug-in's text, valid until
/// this thread's next call).
struct ImageFiles {
    /// Writes 3-channel pixels, 8-bit (`eightBit`, sRGB) or float (linear) as `path`'s extension
    /// says; "unsupported" when no writer knows the format.
    const char* (*write)(const char* path, int width, int height, const void* pixels,
                         bool eightBit);
    /// Reads a file into `pixels`.
    const char* (*read)(const char* path, FilePixels* pixels);
};

} // namespace pathlab::plugin

/// The plug-in's one export.
extern "C" const pathlab::plugin::ImageFiles* pathlab_image_files();
