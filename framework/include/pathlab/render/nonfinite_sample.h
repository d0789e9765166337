#pragma once
/// The first sample of a render whose radiance was NaN or infinite, to report where it was.

#include "pathlab/color.h"

#include <cstdint>
#include <mutex>
#include <optional>

namespace pathlab {

/// A sample whose pathTrace returned NaN or an infinite radiance. The image leaves it out and
/// counts its pixel; this says where to look.
struct NonfiniteSample {
    int x = 0, y = 0;         ///< the pixel, from the top left
    uint64_t sampleIndex = 0; ///< which sample of that pixel (0 is the first of the render)
    /// Closest-hit rays the sample traced, its camera ray included: how deep its path went
    /// (one ray per bounce for labs 2–4; lab 1 branches).
    uint64_t raysTraced = 0;
    Color radiance; ///< what pathTrace returned

    /// By sample index, then pixel: the "first" one is the same whatever order tiles ran in.
    bool before(const NonfiniteSample& other) const {
        if (sampleIndex != other.sampleIndex) return sampleIndex < other.sampleIndex;
        return y != other.y ? y < other.y : x < other.x;
    }
};

/// The first NonfiniteSample of a pass, noted from the renderer's threads. The lock is taken
/// only for a non-finite sample, so a correct lab never pays for it.
class FirstNonfiniteSample {
public:
    void note(const NonfiniteSample& sample) {
        const std::lock_guard<std::mutex> lock(mutex_);
        if (!first_ || sample.before(*first_)) first_ = sample;
    }
    /// Read once the threads are done.
    const std::optional<NonfiniteSample>& first() const { return first_; }

private:
    std::mutex mutex_;
    std::optional<NonfiniteSample> first_;
};

} // namespace pathlab
