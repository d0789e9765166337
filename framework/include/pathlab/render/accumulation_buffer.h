#pragma once
/// Per-pixel running sums of radiance samples: the image so far and how noisy it is.

#include "pathlab/support/check.h"
#include "pathlab/color.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pathlab {

/// For every pixel, the sum and the sum of squares of its samples (per channel), and whether any
/// sample was not finite. Non-finite samples are counted, not added, so one NaN does not hide the
/// rest of the image.
class AccumulationBuffer {
public:
    AccumulationBuffer(int width, int height);

    int width() const { return width_; }
    int height() const { return height_; }
    /// Samples every pixel has received.
    int samplesPerPixel() const { return samplesPerPixel_; }

    void clear();
    /// Called by the renderer when a pass has given every pixel `spp` more samples.
    void finishPass(int spp) { samplesPerPixel_ += spp; }

    /// Adds one sample to `pixel`; a NaN or infinite one is left out and the pixel marked.
    /// Returns whether the sample was finite.
    bool addSample(int pixel, const Color& value) {
        PATHLAB_DCHECK(pixel >= 0 && static_cast<size_t>(pixel) < sum_.size());
        if (!isFinite(value)) {
            nonfinite_[pixel] = 1;
            return false;
        }
        sum_[pixel] += value;
        sumSquares_[pixel] += value * value;
        return true;
    }

    /// The pixel's estimate: the mean of its samples.
    Color mean(int pixel) const;
    /// The sample variance of the pixel's samples (unbiased, per channel).
    Color variance(int pixel) const;
    /// The figures of the whole image so far, from one pass over its pixels.
    struct Summary {
        Color meanRadiance;  ///< per channel, over the pixels
        Color meanVariance;  ///< the per-sample variance, per channel, averaged over the pixels
        int nonfinitePixels; ///< pixels with at least one NaN or infinite sample
        double noise;        ///< imageNoise (pathlab/images/image_noise.h)
    };
    Summary summary() const;

    /// The image as linear RGB floats, row-major from the top-left corner.
    std::vector<float> meanImage() const;
    /// The same into `rgb`, reusing its memory (the viewer does this every frame).
    void meanImage(std::vector<float>& rgb) const;
    /// Each pixel's sample variance (variance()) laid out as meanImage lays out the means: what
    /// the noise maps are made from (pathlab/images/pixel_noise_map.h).
    void varianceImage(std::vector<float>& rgb) const;

private:
    /// Pixels per chunk of the passes over the whole image (summary, meanImage, varianceImage),
    /// which run in parallel: the window's render thread makes one of each every frame while the
    /// render threads wait, which on many cores would take longer than the frame's render.
    /// 4096: 64 chunks at 512x512, enough for a lab machine's 64 cores.
    static constexpr int PixelsPerChunk = 4096;
    size_t chunkCount() const;
    /// perChunk(chunk, firstPixel, endPixel) for every chunk, in parallel.
    template <typename PerChunk> void forEachChunk(const PerChunk& perChunk) const;

    int width_, height_;
    int samplesPerPixel_ = 0;
    std::vector<Color> sum_;
    std::vector<Color> sumSquares_;
    std::vector<uint8_t> nonfinite_;
};

} // namespace pathlab
