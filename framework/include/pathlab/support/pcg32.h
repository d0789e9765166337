#pragma once
/// PCG32 (O'Neill, "PCG: A Family of Simple Fast Space-Efficient Statistically Good Algorithms
/// for Random Number Generation", 2014): 64-bit state, 32-bit output, 2^63 selectable streams.
/// The tests' own generator, independent of the one the renderer hands a lab
/// (random_stream.h), so that a test's inputs share no structure with what it tests.

#include <cstdint>

namespace pathlab {

class Pcg32 {
public:
    Pcg32() { seed(0, 0); }
    Pcg32(uint64_t initState, uint64_t stream) { seed(initState, stream); }

    /// The reference pcg32_srandom_r: any state and any stream are valid.
    void seed(uint64_t initState, uint64_t stream) {
        state_ = 0;
        increment_ = (stream << 1u) | 1u;
        nextUint();
        state_ += initState;
        nextUint();
    }

    uint32_t nextUint() {
        const uint64_t old = state_;
        state_ = old * 6364136223846793005ull + increment_;
        const auto xorShifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
        const auto rotation = static_cast<uint32_t>(old >> 59u);
        return (xorShifted >> rotation) | (xorShifted << ((32u - rotation) & 31u));
    }

    /// A float uniform in [0,1): the top 24 bits scaled exactly, so 1.0f is never returned.
    float nextFloat() { return static_cast<float>(nextUint() >> 8) * 0x1p-24f; }

    /// Whether two generators are at the same point of the same stream (the path inspector
    /// counts a lab's draws between two calls by stepping one until it meets the other).
    bool operator==(const Pcg32& other) const {
        return state_ == other.state_ && increment_ == other.increment_;
    }

private:
    uint64_t state_ = 0;
    uint64_t increment_ = 1;
};

} // namespace pathlab
