#pragma once
/// The scene ready to trace: Embree's acceleration structure, the triangles' data and the lights.

#include "pathlab/render/camera_packet.h"
#include "pathlab/hit.h"
#include "pathlab/render/light_sampler.h"
#include "pathlab/ray.h"
#include "pathlab/scene_io/scene.h"

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

// Embree's scene handle (RTCScene is RTCSceneTy* in Embree 3 and 4), declared here so this header
// does not pull in Embree.
struct RTCSceneTy;

namespace pathlab {

/// Owns the Embree device and scene built from a Scene. Tracing is thread-safe.
class RenderScene {
public:
    explicit RenderScene(Scene scene);
    ~RenderScene();
    RenderScene(const RenderScene&) = delete;
    RenderScene& operator=(const RenderScene&) = delete;

    /// The closest surface along `ray`.
    Hit intersect(const Ray& ray) const;
    /// Traces the camera rays of `packet` in one query and stores what each found.
    void intersect(CameraPacket& packet) const;
    /// What the ray in `lane` of a traced packet found: the Hit intersect(packet.rays[lane])
    /// returns.
    Hit hit(const CameraPacket& packet, int lane) const;
    /// Whether anything lies between `from` and `to` (both excluded).
    bool occluded(const Vec3& from, const Vec3& to) const;

    const Scene& scene() const { return scene_; }
    const LightSampler& lights() const { return lights_; }
    /// Embree's scene, for timing its traversal alone (the benchmark).
    RTCSceneTy* embreeScene() const;

private:
    /// What shading a hit needs of its triangle, copied out of the Scene's arrays so a hit reads
    /// one cache line instead of five scattered ones.
    struct alignas(64) TriangleRecord {
        Vec3 a, b, c;           ///< vertex positions, counter-clockwise
        Vec3 geometricNormal;   ///< normalize(cross(b - a, c - a)), computed once
        uint32_t material;      ///< index into Scene::materials
        uint32_t vertexNormals; ///< index into vertexNormals_, or Flat when the OBJ gave none
    };
    static constexpr uint32_t Flat = ~0u;

    /// The Hit of `ray` on `triangle` at distance t and barycentrics (u, v), as Embree found it.
    Hit shade(const Ray& ray, uint32_t triangle, float distance, float u, float v) const;

    struct Embree;
    Scene scene_;
    LightSampler lights_;
    std::vector<TriangleRecord> triangles_;
    std::vector<std::array<Vec3, 3>> vertexNormals_; ///< per triangle with vertex normals
    std::unique_ptr<Embree> embree_;
};

} // namespace pathlab
