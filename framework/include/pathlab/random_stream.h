#pragma once
/// Counter-based random numbers: the n-th number of a stream is a hash of (start + n·γ), SplitMix64
/// (Steele, Lea and Flood, "Fast Splittable Pseudorandom Number Generators", OOPSLA 2014). A
/// stream is only its position, so starting one is an add: the renderer starts one per sample.

#include <cstdint>

namespace pathlab {

/// SplitMix64's odd increment, 2^64 / φ: successive positions are far apart in every bit.
constexpr uint64_t StreamGamma = 0x9e3779b97f4a7c15ull;

/// Mixes a 64-bit value into a well-distributed one (SplitMix64's finaliser, after its step).
/// Neighbouring inputs give unrelated outputs.
constexpr uint64_t mix64(uint64_t z) {
    z += StreamGamma;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

/// One stream of SplitMix64: every stream with the same γ is a window of the one sequence
/// mix64(n·γ), so two streams are independent as long as their windows do not overlap (the
/// renderer's start 2^32 draws apart within a pixel, and at hashed positions between pixels).
class RandomStream {
public:
    explicit RandomStream(uint64_t position = 0) : position_(position) {}

    uint64_t nextUint64() {
        const uint64_t value = mix64(position_);
        position_ += StreamGamma;
        return value;
    }

    /// A float uniform in [0,1): the top 24 bits scaled exactly, so 1.0f is never returned.
    float nextFloat() { return static_cast<float>(nextUint64() >> 40) * 0x1p-24f; }

    /// Where the stream stands (the path inspector counts a lab's draws between two calls by
    /// stepping one copy until it meets the other).
    bool operator==(const RandomStream& other) const { return position_ == other.position_; }

private:
    uint64_t position_;
};

} // namespace pathlab
