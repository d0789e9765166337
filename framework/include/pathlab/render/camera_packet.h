#pragma once
/// Camera rays traced together: one Embree packet query for several rays of a tile.

#include "pathlab/ray.h"

#include <cstdint>
#include <cstring>

namespace pathlab {

/// Up to Size camera rays and, once RenderScene::intersect(CameraPacket&) has traced them, what
/// each found. Neighbouring camera rays share their path through Embree's tree, so a packet
/// query traces them several times faster than one query each, and finds the same hits.
struct CameraPacket {
    static constexpr int Size = 8; ///< Embree's 8-wide queries: AVX2, emulated where narrower

    int count = 0; ///< rays in use
    Ray rays[Size];
    // The hits, as RenderScene::intersect(rays[i]) reports them.
    bool found[Size];        ///< the ray hit something
    float distance[Size];    ///< ray parameter t of the hit
    float u[Size], v[Size];  ///< barycentric coordinates of the hit
    uint32_t triangle[Size]; ///< index of the triangle hit

    /// Whether `ray` is, bit for bit, the camera ray in `lane`.
    bool holds(int lane, const Ray& ray) const {
        return ray.kind == RayKind::Camera &&
               std::memcmp(&ray.origin, &rays[lane].origin, sizeof(Vec3)) == 0 &&
               std::memcmp(&ray.direction, &rays[lane].direction, sizeof(Vec3)) == 0;
    }
};

} // namespace pathlab
