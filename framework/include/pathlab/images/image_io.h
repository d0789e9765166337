#pragma once
/// Image files: linear radiance in .exr/.pfm/.hdr, sRGB in .png. .pfm is read and written here;
/// the others through OpenImageIO, in a plug-in loaded on first use (image_files.h).

#include <string>
#include <vector>

namespace pathlab {

/// Throws InputError unless `path` has a supported extension and its folder exists and is
/// writable; called before rendering so a bad -o costs no render time.
void checkImageOutputPath(const std::string& path, const std::string& option = "-o");

/// Writes linear RGB floats (row-major, top-left first). .png is sRGB-encoded, clamped to [0,1]
/// and 8-bit; .exr, .pfm and .hdr keep linear floats. Atomic: writes a temporary file in the same
/// folder, then renames it over `path`, so a reader never sees half an image.
void writeImage(const std::string& path, int width, int height, const std::vector<float>& rgb);

/// Writes display-ready 8-bit sRGB RGB bytes (row-major, top-left first) as they are, e.g. a
/// capture of the viewer's window. Atomic like writeImage.
void writeDisplayImage(const std::string& path, int width, int height,
                       const std::vector<unsigned char>& rgb8);

/// A linear RGB image read from a file (any format OpenImageIO reads; 8-bit files are decoded
/// from sRGB). Throws InputError if it cannot.
struct Image {
    int width = 0, height = 0;
    std::vector<float> rgb;
};
Image readImage(const std::string& path);

/// The sRGB transfer function of a linear value in [0,1].
float linearToSrgb(float linear);

/// The image-file plug-in's file name as this platform's linker names it
/// ("libpathlab_image_files.so", ".dylib", "pathlab_image_files.dll"); it sits beside the programs.
const char* imagePluginFileName();

} // namespace pathlab
