#include "pathlab/accumulation_buffer.h"

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
    const Color v = (sumSquares_[pixel] - m * m * static_cast<float>(n)) / static_cast<float>(n - 1);
    // Rounding can make a tiny variance slightly negative.
    return {std::fmax(v.r, 0.0f), std::fmax(v.g, 0.0f), std::fmax(v.b, 0.0f)};
}

Color AccumulationBuffer::meanRadiance() const {
    double r = 0, g = 0, b = 0;
    for (size_t i = 0; i < sum_.size(); ++i) {
        r += sum_[i].r, g += sum_[i].g, b += sum_[i].b;
    }
    const double n = static_cast<double>(sum_.size()) * std::max(samplesPerPixel_, 1);
    return {static_cast<float>(r / n), static_cast<float>(g / n), static_cast<float>(b / n)};
}

int AccumulationBuffer::nonfinitePixels() const {
    int count = 0;
    for (uint8_t flag : nonfinite_) count += flag;
    return count;
}

float AccumulationBuffer::meanRelativeStandardError() const {
    if (samplesPerPixel_ < 2) return 0.0f;
    double total = 0;
    long counted = 0;
    for (int i = 0; i < static_cast<int>(sum_.size()); ++i) {
        const Color m = mean(i), v = variance(i);
        for (int c = 0; c < 3; ++c) {
            if (m[c] <= 1e-6f) continue; // black pixels have no relative error
            total += std::sqrt(v[c] / samplesPerPixel_) / m[c];
            ++counted;
        }
    }
    return counted > 0 ? static_cast<float>(total / counted) : 0.0f;
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

} // namespace pathlab
