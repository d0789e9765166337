#include "pathlab/render/render_scene.h"
#include "pathlab/support/check.h"

#include "pathlab/render/embree_rays.h"
#include "pathlab/support/input_error.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace pathlab {

namespace {

void reportEmbreeError(void*, RTCError code, const char* message) {
    if (code != RTC_ERROR_NONE)
        throw std::runtime_error(std::string("Embree error: ") + (message ? message : "unknown"));
}

} // namespace

struct RenderScene::Embree {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    ~Embree() {
        if (scene) rtcReleaseScene(scene);
        if (device) rtcReleaseDevice(device);
    }
};

RenderScene::RenderScene(Scene scene)
    : scene_(std::move(scene)), lights_(scene_), embree_(std::make_unique<Embree>()) {
    if (scene_.triangles.empty()) throw InputError("the scene has no triangles to render");
    embree_->device = rtcNewDevice(nullptr);
    if (!embree_->device) throw std::runtime_error("Embree could not create a device");
    rtcSetDeviceErrorFunction(embree_->device, reportEmbreeError, nullptr);

    embree_->scene = rtcNewScene(embree_->device);
    // Embree's default, fast traversal. Its robust mode (RTC_SCENE_FLAG_ROBUST) costs about 20%
    // of the render time on PathLab's scenes and bought nothing measurable: in the closed
    // furnaces, whose every escaped path would darken the image, 1M samples give the same mean
    // to 1e-7 either way, and the furnace tests hold without it.
    rtcSetSceneBuildQuality(embree_->scene, RTC_BUILD_QUALITY_HIGH);

    RTCGeometry mesh = rtcNewGeometry(embree_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    // Embree reads vertex buffers with 16-byte loads, so the buffer it allocates is padded; ours
    // (Vec3 arrays) are copied in rather than shared.
    auto* vertices = static_cast<float*>(
        rtcSetNewGeometryBuffer(mesh, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                3 * sizeof(float), scene_.positions.size()));
    for (size_t i = 0; i < scene_.positions.size(); ++i) {
        vertices[3 * i + 0] = scene_.positions[i].x;
        vertices[3 * i + 1] = scene_.positions[i].y;
        vertices[3 * i + 2] = scene_.positions[i].z;
    }
    auto* indices = static_cast<uint32_t*>(
        rtcSetNewGeometryBuffer(mesh, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(uint32_t), scene_.triangles.size()));
    for (size_t i = 0; i < scene_.triangles.size(); ++i)
        for (int k = 0; k < 3; ++k) indices[3 * i + k] = scene_.triangles[i][k];
    rtcCommitGeometry(mesh);
    rtcAttachGeometry(embree_->scene, mesh);
    rtcReleaseGeometry(mesh);
    rtcCommitScene(embree_->scene);

    triangles_.resize(scene_.triangles.size());
    for (size_t i = 0; i < scene_.triangles.size(); ++i) {
        const auto& tri = scene_.triangles[i];
        TriangleRecord& t = triangles_[i];
        t.a = scene_.positions[tri[0]];
        t.b = scene_.positions[tri[1]];
        t.c = scene_.positions[tri[2]];
        // Our own counter-clockwise normal, not Embree's Ng, whose orientation convention
        // differs between versions and builds.
        t.geometricNormal = normalize(cross(t.b - t.a, t.c - t.a));
        t.material = scene_.triangleMaterials[i];
        const std::array<Vec3, 3> normals = {scene_.vertexNormals[tri[0]],
                                             scene_.vertexNormals[tri[1]],
                                             scene_.vertexNormals[tri[2]]};
        const bool flat = std::all_of(normals.begin(), normals.end(),
                                      [](const Vec3& n) { return dot(n, n) == 0; });
        t.vertexNormals = flat ? Flat : static_cast<uint32_t>(vertexNormals_.size());
        if (!flat) vertexNormals_.push_back(normals);
    }
}

RenderScene::~RenderScene() = default;

Hit RenderScene::intersect(const Ray& ray) const {
    RTCRayHit rayHit = embree::closestHitQuery(ray);
    embree::intersect1(embree_->scene, rayHit, ray.kind == RayKind::Camera);
    if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return Hit();
    return shade(ray, rayHit.hit.primID, rayHit.ray.tfar, rayHit.hit.u, rayHit.hit.v);
}

void RenderScene::intersect(CameraPacket& packet) const {
    alignas(32) int valid[CameraPacket::Size];
    for (int i = 0; i < CameraPacket::Size; ++i) valid[i] = i < packet.count ? -1 : 0;
    RTCRayHit8 rayHits = embree::cameraPacketQuery(packet);
    embree::intersect8(embree_->scene, valid, rayHits);
    for (int i = 0; i < packet.count; ++i) {
        packet.found[i] = rayHits.hit.geomID[i] != RTC_INVALID_GEOMETRY_ID;
        packet.distance[i] = rayHits.ray.tfar[i];
        packet.u[i] = rayHits.hit.u[i];
        packet.v[i] = rayHits.hit.v[i];
        packet.triangle[i] = rayHits.hit.primID[i];
    }
}

Hit RenderScene::hit(const CameraPacket& packet, int lane) const {
    if (!packet.found[lane]) return Hit();
    return shade(packet.rays[lane], packet.triangle[lane], packet.distance[lane], packet.u[lane],
                 packet.v[lane]);
}

Hit RenderScene::shade(const Ray& ray, uint32_t triangle, float distance, float u, float v) const {
    const TriangleRecord& t = triangles_[triangle];
    const float w = 1.0f - u - v;
    Hit hit;
    hit.found = true;
    hit.distance = distance;
    // From the barycentrics rather than origin + t·direction: exactly on the triangle's plane
    // up to rounding, whatever the distance travelled.
    hit.position = t.a * w + t.b * u + t.c * v;
    hit.frontFace = dot(t.geometricNormal, ray.direction) < 0;
    const float side = hit.frontFace ? 1.0f : -1.0f;
    hit.geometricNormal = t.geometricNormal * side;
    hit.normal = hit.geometricNormal;
    if (t.vertexNormals != Flat) {
        const std::array<Vec3, 3>& n = vertexNormals_[t.vertexNormals];
        Vec3 shading = n[0] * w + n[1] * u + n[2] * v;
        if (dot(shading, shading) > 0) {
            shading = normalize(shading);
            // Keep the shading normal on the geometric normal's side so both face the ray.
            if (dot(shading, t.geometricNormal) < 0) shading = -shading;
            hit.normal = shading * side;
        }
    }
    hit.material = scene_.materials[t.material];
    if (hit.frontFace) hit.emitted = hit.material.Ke;
    // hit.h promises unit normals facing the ray's side: diffuseRay and directLight rely on it.
    PATHLAB_DCHECK(std::abs(dot(hit.normal, hit.normal) - 1.0f) < 1e-3f);
    PATHLAB_DCHECK(dot(hit.geometricNormal, ray.direction) <= 0);
    return hit;
}

bool RenderScene::occluded(const Vec3& from, const Vec3& to) const {
    RTCRay ray = embree::occlusionQuery(from, to);
    return embree::occluded1(embree_->scene, ray);
}

RTCSceneTy* RenderScene::embreeScene() const { return embree_->scene; }

} // namespace pathlab
