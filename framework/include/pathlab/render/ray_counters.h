#pragma once
/// Counts of rays traced, kept per tile and summed once per tile so counting costs nothing.

#include <cstdint>

namespace pathlab {

struct RayCounters {
    uint64_t intersect = 0; ///< closest-hit rays (camera and bounce rays)
    uint64_t occluded = 0;  ///< shadow rays of next-event estimation

    RayCounters& operator+=(const RayCounters& o) {
        intersect += o.intersect;
        occluded += o.occluded;
        return *this;
    }
    uint64_t total() const { return intersect + occluded; }
};

} // namespace pathlab
