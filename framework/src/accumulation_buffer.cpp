#include "pathlab/accumulation_buffer.h"

#include "pathlab/image_noise.h"

#include <algorithm>
#include <cmath>

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

Color AccumulationBuffer::mean(int pixel) const {
    return samplesPerPixel_ > 0 ? sum_[pixel] / static_cast<float>(samplesPerPixel_) : Color();
}

Color AccumulationBuffer::variance(int pixel) const {
    const int n = samplesPerPixel_;
    if (n < 2) return Color();
    const Color m = mean(pixel);
    const Color v =
        (sumSquares_[pixel] - m * m * static_cast<float>(n)) / static_cast<float>(n - 1);
    // Rounding can make a tiny variance slightly negative.
    return {std::fmax(v.r, 0.0f), std::fmax(v.g, 0.0f), std::fmax(v.b, 0.0f)};
}

AccumulationBuffer::Summary AccumulationBuffer::summary() const {
    double radiance[3] = {0, 0, 0}, sampleVariance[3] = {0, 0, 0};
    int nonfinite = 0;
    for (int i = 0; i < static_cast<int>(sum_.size()); ++i) {
        const Color m = mean(i), v = variance(i);
        for (int c = 0; c < 3; ++c) radiance[c] += m[c], sampleVariance[c] += v[c];
        nonfinite += nonfinite_[i];
    }
    const double pixels = std::max<double>(1, static_cast<double>(sum_.size()));
    auto perPixel = [&](const double* total) {
        return Color(static_cast<float>(total[0] / pixels), static_cast<float>(total[1] / pixels),
                     static_cast<float>(total[2] / pixels));
    };
    Summary s{perPixel(radiance), perPixel(sampleVariance), nonfinite, 0};
    s.noise = imageNoise(s.meanVariance, s.meanRadiance, samplesPerPixel_);
    return s;
}

std::vector<float> AccumulationBuffer::meanImage() const {
    std::vector<float> rgb;
    meanImage(rgb);
    return rgb;
}

void AccumulationBuffer::meanImage(std::vector<float>& rgb) const {
    rgb.resize(3 * sum_.size());
    for (size_t i = 0; i < sum_.size(); ++i) {
        const Color m = mean(static_cast<int>(i));
        rgb[3 * i] = m.r, rgb[3 * i + 1] = m.g, rgb[3 * i + 2] = m.b;
    }
}

void AccumulationBuffer::varianceImage(std::vector<float>& rgb) const {
    rgb.resize(3 * sum_.size());
    for (size_t i = 0; i < sum_.size(); ++i) {
        const Color v = variance(static_cast<int>(i));
        rgb[3 * i] = v.r, rgb[3 * i + 1] = v.g, rgb[3 * i + 2] = v.b;
    }
}

} // namespace pathlab
