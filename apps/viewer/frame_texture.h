#pragma once
/// The frame shown: its image as the view mode shows it, in an OpenGL texture that fills the
/// window.

#include "pathlab/images/false_colour.h"
#include "pathlab/images/image_io.h"
#include "view_mode.h"

#include <optional>
#include <vector>

namespace pathlab {
struct Frame;
}

namespace pathlab::viewer {

class FrameTexture {
public:
    /// Needs the window's OpenGL context current, as does everything below.
    FrameTexture();
    ~FrameTexture();
    FrameTexture(const FrameTexture&) = delete;
    FrameTexture& operator=(const FrameTexture&) = delete;

    /// The frame's image, its difference to `reference`, the split view or a map, into the
    /// texture. A map needs the frame's variance (ProgressiveRenderer::setVarianceWanted); until
    /// a frame brings it, the image is shown.
    void upload(const Frame& frame, ViewMode mode, const Image& reference);
    /// The texture over the whole viewport; nothing before the first upload.
    void draw() const;
    bool hasImage() const { return hasImage_; }
    /// The median relative difference of the last difference view uploaded, for the panel.
    float medianDifference() const { return medianDifference_; }
    /// The log scale of the map uploaded last, for the panel's scale bar; none when the texture
    /// holds no map.
    const std::optional<LogScale>& mapScale() const { return mapScale_; }

private:
    std::vector<unsigned char> rgba_; ///< kept, so that a frame allocates nothing
    unsigned texture_ = 0;
    bool hasImage_ = false;
    float medianDifference_ = 0;
    std::optional<LogScale> mapScale_;
};

} // namespace pathlab::viewer
