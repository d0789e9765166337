#include "screenshots.h"

#include "runner/progressive_renderer.h"

#include "pathlab/images/image_io.h"
#include "pathlab/support/input_error.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cstdio>
#include <vector>

namespace pathlab::viewer {

bool saveScreenshot(const Frame& frame, const std::string& requested) {
    if (frame.image.empty()) return true;
    const ViewSettings& s = frame.settings;
    const int w = s.width, h = s.height;
    bool saved = true;
    try {
        if (!requested.empty()) {
            writeImage(requested, w, h, frame.image);
            std::printf("screenshot %s (%d spp)\n", requested.c_str(), frame.stats.spp);
        } else {
            const std::string base = "pathlab-" + std::string(labName(s.lab)) + "-" +
                                     std::string(implementationName(s.implementation)) + "-" +
                                     std::to_string(frame.stats.spp) + "spp";
            writeImage(base + ".exr", w, h, frame.image);
            writeImage(base + ".png", w, h, frame.image);
            std::printf("screenshot %s.exr and %s.png\n", base.c_str(), base.c_str());
        }
    } catch (const InputError& error) {
        std::fprintf(stderr, "viewer: %s\n", error.what());
        saved = false;
    }
    std::fflush(stdout);
    return saved;
}

bool captureWindow(const std::string& path, int width, int height) {
    std::vector<unsigned char> bottomUp(3 * static_cast<size_t>(width) * height),
        rgb(bottomUp.size());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(GL_BACK);
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, bottomUp.data());
    const size_t row = 3 * static_cast<size_t>(width);
    for (int y = 0; y < height; ++y) // OpenGL's rows start at the bottom
        std::copy_n(&bottomUp[(height - 1 - y) * row], row, &rgb[y * row]);
    try {
        writeDisplayImage(path, width, height, rgb);
        std::printf("window capture %s\n", path.c_str());
    } catch (const InputError& error) {
        std::fprintf(stderr, "viewer: %s\n", error.what());
        return false;
    }
    return true;
}

} // namespace pathlab::viewer
