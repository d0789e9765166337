#include "pathlab/scene_io/scene_defaults.h"

#include "pathlab/constants.h"
#include "pathlab/scene_io/model_coverage.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace pathlab {

Vec3 framingDirection() { return normalize(Vec3{0.5f, 0.35f, 1.0f}); }

namespace {

/// The normal of the largest triangle, turned to the front: a flat model's face.
Vec3 largestFace(const Scene& scene) {
    Vec3 best{0, 0, 0};
    for (const auto& t : scene.triangles) {
        const Vec3& a = scene.positions[t[0]];
        const Vec3 areaNormal = cross(scene.positions[t[1]] - a, scene.positions[t[2]] - a);
        if (length(areaNormal) > length(best)) best = areaNormal;
    }
    if (length(best) == 0) return framingDirection();
    return normalize(dot(best, framingDirection()) < 0 ? -best : best);
}

/// The camera's frame for looking along -towardCamera with `up` roughly up in the image.
struct ViewFrame {
    Vec3 right, up, towardCamera;
};

ViewFrame viewFrame(const Vec3& towardCamera, const Vec3& up) {
    Vec3 right = cross(up, towardCamera);
    if (length(right) < 1e-6f) // looking straight along `up`: any right will do
        right =
            cross(std::abs(towardCamera.x) < 0.9f ? Vec3{1, 0, 0} : Vec3{0, 1, 0}, towardCamera);
    right = normalize(right);
    return {right, cross(towardCamera, right), towardCamera};
}

/// Calls `visit` with each vertex a triangle of `scene` uses (some more than once).
template <typename Visit> void forEachTriangleVertex(const Scene& scene, Visit visit) {
    for (const auto& triangle : scene.triangles)
        for (const uint32_t v : triangle) visit(scene.positions[v]);
}

/// Moves `centre` across the view (not along it) to the middle of the model's extent as seen
/// along the frame's axis, so that the fit below wastes no side of the image.
Vec3 centredAcross(const Scene& scene, const ViewFrame& frame, const Vec3& centre) {
    constexpr float inf = std::numeric_limits<float>::infinity();
    float lo[2] = {inf, inf}, hi[2] = {-inf, -inf};
    forEachTriangleVertex(scene, [&](const Vec3& p) {
        const float x = dot(p - centre, frame.right), y = dot(p - centre, frame.up);
        lo[0] = std::min(lo[0], x), hi[0] = std::max(hi[0], x);
        lo[1] = std::min(lo[1], y), hi[1] = std::max(hi[1], y);
    });
    if (!(lo[0] <= hi[0])) return centre;
    return centre + frame.right * (0.5f * (lo[0] + hi[0])) + frame.up * (0.5f * (lo[1] + hi[1]));
}

/// The least distance from `lookAt` back along the frame's axis at which every vertex is within
/// FramingFill of the image's half-extents tanX and tanY: a vertex at (x, y) across the view and
/// z towards the camera is in view from distance D when |x| <= (D - z)·tanX, likewise for y.
float fittingDistance(const Scene& scene, const ViewFrame& frame, const Vec3& lookAt, float tanX,
                      float tanY, float radius) {
    float distance = 0;
    forEachTriangleVertex(scene, [&](const Vec3& p) {
        const Vec3 d = p - lookAt;
        const float x = std::abs(dot(d, frame.right)), y = std::abs(dot(d, frame.up));
        const float z = dot(d, frame.towardCamera);
        // Never closer than a little in front of the nearest vertex.
        distance = std::max({distance, z + 0.01f * radius, z + x / (FramingFill * tanX),
                             z + y / (FramingFill * tanY)});
    });
    return distance > 0 ? distance : radius;
}

/// `camera` (its up vector and field of view) placed to look at the model from `towardCamera`,
/// at `lookAt` or, if that is not given, at the model centred as seen from there.
CameraSettings placed(const Scene& scene, const BoundingBox& bounds, CameraSettings camera,
                      const Vec3& towardCamera, bool lookAtGiven, float aspect) {
    const ViewFrame frame = viewFrame(towardCamera, camera.up);
    if (!lookAtGiven) camera.lookAt = centredAcross(scene, frame, bounds.centre());
    const float tanY = std::tan(0.5f * camera.fovDegrees * Pi / 180.0f);
    const float radius = bounds.radius() > 0 ? bounds.radius() : 1.0f;
    camera.position = camera.lookAt + towardCamera * fittingDistance(scene, frame, camera.lookAt,
                                                                     tanY * aspect, tanY, radius);
    return camera;
}

/// The directions a camera PathLab places may look from, after the usual one: the largest
/// face's normal and the 26 of the cube around the model (faces, edges, corners), none
/// straight along `up`, where a camera has no left or right (those lean to the usual side).
std::vector<Vec3> otherDirections(const Scene& scene, const Vec3& up) {
    std::vector<Vec3> directions = {largestFace(scene)};
    for (int x = -1; x <= 1; ++x)
        for (int y = -1; y <= 1; ++y)
            for (int z = -1; z <= 1; ++z)
                if (x || y || z)
                    directions.push_back(normalize(Vec3{float(x), float(y), float(z)}));
    const Vec3 upward = normalize(up);
    const Vec3 usual = framingDirection();
    const Vec3 front = normalize(usual - upward * dot(usual, upward));
    for (Vec3& d : directions)
        if (std::abs(dot(d, upward)) > 0.97f) d = normalize(d + front * 0.3f);
    return directions;
}

/// Whether `camera` stands back from the model at least its radius (the sphere around its box)
/// from every vertex: a view along a row of objects, from close behind the first, fills the
/// image with that one and hides the rest.
bool standsBack(const Scene& scene, float radius, const CameraSettings& camera) {
    bool back = true;
    forEachTriangleVertex(scene, [&](const Vec3& p) {
        back = back && length(p - camera.position) >= FramingLeastNearDistance * radius;
    });
    return back;
}

} // namespace

Vec3 framingDirectionFor(const Scene& scene, const CameraSettings& camera, bool lookAtGiven,
                         float aspect) {
    const BoundingBox bounds = scene.bounds();
    const Vec3 usual = framingDirection();
    const double usualShare =
        coveredShare(scene, placed(scene, bounds, camera, usual, lookAtGiven, aspect), aspect);
    if (usualShare >= FramingEnoughShare) return usual;
    Vec3 best = usual;
    double bestShare = usualShare;
    for (const Vec3& d : otherDirections(scene, camera.up)) {
        const CameraSettings candidate = placed(scene, bounds, camera, d, lookAtGiven, aspect);
        if (!standsBack(scene, bounds.radius(), candidate)) continue;
        const double share = coveredShare(scene, candidate, aspect);
        // Of views that fill the image alike (a flat model from above and from below), the one
        // nearer the usual direction.
        const bool tie = std::abs(share - bestShare) < 1e-9;
        if (share > bestShare + 1e-9 || (tie && dot(d, usual) > dot(best, usual)))
            best = d, bestShare = share;
    }
    return bestShare > 0 && bestShare >= FramingBetterBy * usualShare ? best : usual;
}

CameraSettings framingCamera(const Scene& scene, const GivenCamera& given, float aspect) {
    CameraSettings camera = given.settings;
    if (!given.fov) camera.fovDegrees = FramingFovDegrees;
    const BoundingBox bounds = scene.bounds();
    if (given.position) {
        if (!given.lookAt) camera.lookAt = bounds.centre();
    } else {
        const Vec3 towardCamera = given.viewDirection
                                      ? -normalize(*given.viewDirection)
                                      : framingDirectionFor(scene, camera, given.lookAt, aspect);
        camera = placed(scene, bounds, camera, towardCamera, given.lookAt, aspect);
    }
    // A position given at the centre itself would look nowhere: look past it instead.
    if (length(camera.lookAt - camera.position) == 0)
        camera.lookAt = camera.position - framingDirection();
    return camera;
}

bool hasLight(const Scene& scene) {
    if (!scene.pointLights.empty() || !scene.directionalLights.empty()) return true;
    return std::any_of(scene.triangleMaterials.begin(), scene.triangleMaterials.end(),
                       [&](uint32_t m) { return !isBlack(scene.materials[m].Ke); });
}

PointLight headlight(const CameraSettings& camera) {
    const Vec3 toLookAt = camera.lookAt - camera.position;
    const float intensity = Pi * dot(toLookAt, toLookAt);
    return {camera.position, {intensity, intensity, intensity}};
}

} // namespace pathlab
