#include "frame_texture.h"

#include "runner/progressive_renderer.h"

#include "pathlab/images/false_colour.h"
#include "pathlab/images/pixel_efficiency_map.h"
#include "pathlab/images/pixel_noise_map.h"

#include <GLFW/glfw3.h>

namespace pathlab::viewer {

namespace {

/// The split view's image: the shown implementation's left half beside the other's right half.
std::vector<float> splitImage(const Frame& frame) {
    const int w = frame.settings.width, h = frame.settings.height;
    std::vector<float> composed = frame.image;
    for (int y = 0; y < h; ++y)
        for (int x = w / 2; x < w; ++x)
            for (int c = 0; c < 3; ++c)
                composed[3 * (y * w + x) + c] = frame.otherImage[3 * (y * w + x) + c];
    return composed;
}

/// The noise or efficiency view's values, one per pixel (pathlab/images/pixel_noise_map.h,
/// pixel_efficiency_map.h).
std::vector<float> mapValues(const Frame& frame, ViewMode mode) {
    std::vector<float> noise =
        relativeStandardErrorMap(frame.image, frame.variance, frame.stats.spp);
    if (mode == ViewMode::Noise) return noise;
    return efficiencyMap(noise, frame.stats.seconds);
}

} // namespace

FrameTexture::FrameTexture() { glGenTextures(1, &texture_); }

FrameTexture::~FrameTexture() { glDeleteTextures(1, &texture_); }

void FrameTexture::upload(const Frame& frame, ViewMode mode, const Image& reference) {
    const int w = frame.settings.width, h = frame.settings.height;
    mapScale_.reset();
    if (isMapMode(mode) && frame.variance.size() == frame.image.size()) {
        const std::vector<float> values = mapValues(frame, mode);
        mapScale_ = decadeScale(values);
        logScaleImage(values, *mapScale_, rgba_);
    } else if (mode == ViewMode::Difference && reference.width == w && reference.height == h)
        medianDifference_ = relativeDifferenceImage(frame.image, reference.rgb, 0.5f, rgba_);
    else if (mode == ViewMode::Split && !frame.otherImage.empty())
        toDisplay(splitImage(frame), rgba_);
    else
        toDisplay(frame.image, rgba_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba_.data());
    hasImage_ = true;
}

void FrameTexture::draw() const {
    if (!hasImage_) return;
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glBegin(GL_QUADS); // the image's first row is its top: flip t
    glTexCoord2f(0, 1), glVertex2f(-1, -1);
    glTexCoord2f(1, 1), glVertex2f(1, -1);
    glTexCoord2f(1, 0), glVertex2f(1, 1);
    glTexCoord2f(0, 0), glVertex2f(-1, 1);
    glEnd();
    glDisable(GL_TEXTURE_2D);
}

} // namespace pathlab::viewer
