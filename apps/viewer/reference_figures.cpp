#include "reference_figures.h"

#include "pathlab/support/input_error.h"
#include "pathlab/images/relative_mse.h"

#include <cstdio>

namespace pathlab::viewer {

Image readReferenceOfSize(const std::string& path, int width, int height) {
    Image reference;
    try {
        reference = readImage(path);
    } catch (const InputError& error) {
        throw InputError(std::string("option --reference: ") + error.what());
    }
    if (reference.width != width || reference.height != height)
        throw InputError("option --reference: '" + path + "' is " +
                         std::to_string(reference.width) + "x" + std::to_string(reference.height) +
                         ", the render " + std::to_string(width) + "x" + std::to_string(height) +
                         " (make one of this size: viewer ... --size " + std::to_string(width) +
                         " " + std::to_string(height) + " --spp 4096 -o ref.exr)");
    return reference;
}

ReferenceFigures compareWithReference(const std::string& file, const std::vector<float>& image,
                                      const Image& reference) {
    return {file, relativeMse(image, reference.rgb), relMseEpsilon,
            relativeRmse(image, reference.rgb)};
}

std::string referenceLine(const ReferenceFigures& f) {
    char text[160];
    std::snprintf(text, sizeof text, "  against %s: relMSE %.6g (epsilon %g), relative RMSE %.6g",
                  f.file.c_str(), f.relMse, f.relMseEpsilon, f.relativeRmse);
    return text;
}

} // namespace pathlab::viewer
