#pragma once
/// A record of the rays a render traced, so the benchmark can replay them through Embree alone.

#include "pathlab/ray.h"
#include "pathlab/vec3.h"

#include <vector>

namespace pathlab {

/// A shadow ray of next-event estimation: the open segment from a surface point to a light.
struct ShadowSegment {
    Vec3 from, to;
};

/// The rays of a render in the order they were traced (tile by tile).
struct RayLog {
    std::vector<Ray> closestHit;          ///< camera and bounce rays, as pathTrace traced them
    std::vector<ShadowSegment> occlusion; ///< shadow rays

    void append(const RayLog& other) {
        closestHit.insert(closestHit.end(), other.closestHit.begin(), other.closestHit.end());
        occlusion.insert(occlusion.end(), other.occlusion.begin(), other.occlusion.end());
    }
};

} // namespace pathlab
