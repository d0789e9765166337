#pragma once
/// The random numbers one path uses, deterministic per (seed, pixel, sample).

#include "pathlab/random_stream.h"
#include "pathlab/vec3.h"

namespace pathlab {

/// Hands a path its uniform random numbers. The renderer restarts it for every (seed, pixel,
/// sample index) (PathDriver, renderer side), so an image does not depend on thread count or
/// tile order, and two seeds give independent images. A lab draws from it; it cannot restart
/// or replace it (no assignment), which would tie samples together.
class Sampler {
public:
    /// One uniform number in [0,1).
    float get1D() { return rng_.nextFloat(); }
    /// Two uniform numbers in [0,1)².
    Vec2 get2D() {
        const float a = rng_.nextFloat();
        return {a, rng_.nextFloat()};
    }

    Sampler(const Sampler&) = default;
    Sampler& operator=(const Sampler&) = delete;

private:
    friend class PathDriver;
    friend class PathRecorder; // reads where the stream stands, to count a lab's draws
    explicit Sampler(const RandomStream& rng) : rng_(rng) {}
    RandomStream rng_;
};

} // namespace pathlab
