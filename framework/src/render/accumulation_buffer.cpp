#include "pathlab/render/accumulation_buffer.h"

#include "parallel_hand_off.h"

#include "pathlab/images/image_noise.h"

#include <tbb/parallel_for.h>

#include <algorithm>

namespace pathlab {

AccumulationBuffer::AccumulationBuffer(int width, int height)
    : width_(width), height_(height), sum_(static_cast<size_t>(width) * height),
      sumSquares_(sum_.size()), nonfinite_(sum_.size(), 0) {}

void AccumulationBuffer::clear() {
    samplesPerPixel_ = 0;
    std::fill(sum_.begin(), sum_.end(), Color());
    std::fill(sumSquares_.begin(), sumSquares_.end(), Color());
    std::fill(nonfinite_.begin(), nonfinite_.end(), 0);
}

namespace {

// A pixel's mean and sample variance from its sums, for mean() and variance() and for the passes
// over the whole image, which must give the same bits and are kept free of calls.
inline Color meanOf(const Color& sum, int n) {
    return n > 0 ? sum / static_cast<float>(n) : Color();
}

inline Color varianceOf(const Color& sum, const Color& sumSquares, int n) {
    if (n < 2) return Color();
    const Color m = meanOf(sum, n);
    const Color v = (sumSquares - m * m * static_cast<float>(n)) / static_cast<float>(n - 1);
    // Rounding can make a tiny variance slightly negative (and a NaN is no variance either).
    const auto atLeastZero = [](float x) { return x > 0.0f ? x : 0.0f; };
    return {atLeastZero(v.r), atLeastZero(v.g), atLeastZero(v.b)};
}

} // namespace

Color AccumulationBuffer::mean(int pixel) const { return meanOf(sum_[pixel], samplesPerPixel_); }

Color AccumulationBuffer::variance(int pixel) const {
    return varianceOf(sum_[pixel], sumSquares_[pixel], samplesPerPixel_);
}

AccumulationBuffer::Summary AccumulationBuffer::summary() const {
    // Each chunk's sums in parallel, then added in chunk order: the same figures at any thread
    // count. (The window's render thread sums every frame while the render threads wait.)
    struct Sums {
        double radiance[3] = {0, 0, 0}, sampleVariance[3] = {0, 0, 0};
        int nonfinite = 0;
    };
    std::vector<Sums> chunks(chunkCount());
    forEachChunk([&](size_t chunk, int begin, int end) {
        Sums sums; // summed here, stored once: neighbouring chunks' sums share a cache line
        const int n = samplesPerPixel_;
        for (int i = begin; i < end; ++i) {
            const Color m = meanOf(sum_[i], n), v = varianceOf(sum_[i], sumSquares_[i], n);
            for (int c = 0; c < 3; ++c) sums.radiance[c] += m[c], sums.sampleVariance[c] += v[c];
            sums.nonfinite += nonfinite_[i];
        }
        chunks[chunk] = sums;
    });
    Sums total;
    for (const Sums& sums : chunks) {
        for (int c = 0; c < 3; ++c)
            total.radiance[c] += sums.radiance[c],
                total.sampleVariance[c] += sums.sampleVariance[c];
        total.nonfinite += sums.nonfinite;
    }
    const double pixels = std::max<double>(1, static_cast<double>(sum_.size()));
    auto perPixel = [&](const double* sum) {
        return Color(static_cast<float>(sum[0] / pixels), static_cast<float>(sum[1] / pixels),
                     static_cast<float>(sum[2] / pixels));
    };
    Summary s{perPixel(total.radiance), perPixel(total.sampleVariance), total.nonfinite, 0};
    s.noise = imageNoise(s.meanVariance, s.meanRadiance, samplesPerPixel_);
    return s;
}

size_t AccumulationBuffer::chunkCount() const {
    return (sum_.size() + PixelsPerChunk - 1) / PixelsPerChunk;
}

template <typename PerChunk> void AccumulationBuffer::forEachChunk(const PerChunk& perChunk) const {
    const int pixels = static_cast<int>(sum_.size());
    // Their addresses name the hand-offs to TSan; static, so that a task names them without
    // reading the loop's closure (parallel_hand_off.h).
    static const char loopStarts = 0, chunksFinished = 0;
    releaseTo(&loopStarts);
    tbb::parallel_for(size_t(0), chunkCount(), [&](size_t chunk) {
        acquireFrom(&loopStarts);
        const int begin = static_cast<int>(chunk * PixelsPerChunk);
        perChunk(chunk, begin, std::min(pixels, begin + PixelsPerChunk));
        releaseTo(&chunksFinished);
    });
    acquireFrom(&chunksFinished);
}

std::vector<float> AccumulationBuffer::meanImage() const {
    std::vector<float> rgb;
    meanImage(rgb);
    return rgb;
}

void AccumulationBuffer::meanImage(std::vector<float>& rgb) const {
    rgb.resize(3 * sum_.size());
    forEachChunk([&](size_t, int begin, int end) {
        for (int i = begin; i < end; ++i) {
            const Color m = meanOf(sum_[i], samplesPerPixel_);
            const size_t at = 3 * static_cast<size_t>(i);
            rgb[at] = m.r, rgb[at + 1] = m.g, rgb[at + 2] = m.b;
        }
    });
}

void AccumulationBuffer::varianceImage(std::vector<float>& rgb) const {
    rgb.resize(3 * sum_.size());
    forEachChunk([&](size_t, int begin, int end) {
        for (int i = begin; i < end; ++i) {
            const Color v = varianceOf(sum_[i], sumSquares_[i], samplesPerPixel_);
            const size_t at = 3 * static_cast<size_t>(i);
            rgb[at] = v.r, rgb[at + 1] = v.g, rgb[at + 2] = v.b;
        }
    });
}

} // namespace pathlab
