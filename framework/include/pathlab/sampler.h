#pragma once
/// The random numbers one path uses, deterministic per (seed, pixel, sample).

#include "pathlab/pcg32.h"
#include "pathlab/vec3.h"

#include <cstdint>

namespace pathlab {

/// Hands a path its uniform random numbers. The renderer restarts it for every (seed, pixel,
/// sample index), so an image does not depend on thread count or tile order, and two seeds
/// give independent images.
class Sampler {
public:
    /// Restarts the sequence for one sample of one pixel.
    void startSample(uint64_t seed, uint64_t pixelIndex, uint64_t sampleIndex) {
        const uint64_t key = mix64(mix64(mix64(seed) ^ pixelIndex) ^ sampleIndex);
        rng_.seed(key, mix64(key ^ 0x5851f42d4c957f2dull));
    }

    /// One uniform number in [0,1).
    float get1D() { return rng_.nextFloat(); }
    /// Two uniform numbers in [0,1)².
    Vec2 get2D() {
        const float a = rng_.nextFloat();
        return {a, rng_.nextFloat()};
    }

private:
    Pcg32 rng_;
};

} // namespace pathlab
