#include "pathlab/scattering.h"

#include "pathlab/support/check.h"
#include "pathlab/cosine_hemisphere.h"
#include "pathlab/render/ray_origin.h"
#include "pathlab/orthonormal_basis.h"
#include "pathlab/render/specular.h"

#include <cmath>
#include <cstdio>

namespace pathlab {

namespace {

/// The three bounces need a surface to leave: a missed hit has no position or normal.
void checkFound(const Hit& hit, const char* bounce, CallSite caller) {
    PATHLAB_CHECK_CALLER(hit.found, caller,
                         std::string(bounce) +
                             " needs a surface: bounce only after `if (!hit)` has returned "
                             "for a ray that left the scene");
}

std::string vectorText(const Vec3& v) {
    char text[96];
    std::snprintf(text, sizeof text, "(%.6g, %.6g, %.6g)", v.x, v.y, v.z);
    return text;
}

} // namespace

Ray diffuseRay(const Hit& hit, Vec2 u, CallSite caller) {
    checkFound(hit, "diffuseRay(hit, u)", caller);
    const Vec3 direction = sampleCosineHemisphere(hit.normal, u);
    return {offsetRayOrigin(hit, direction), direction, RayKind::Diffuse};
}

Ray mirrorRay(const Ray& ray, const Hit& hit, CallSite caller) {
    checkFound(hit, "mirrorRay(ray, hit)", caller);
    const Vec3 direction = normalize(reflect(ray.direction, hit.normal));
    return {offsetRayOrigin(hit, direction), direction, RayKind::Specular};
}

Ray refractionRay(const Ray& ray, const Hit& hit, CallSite caller) {
    checkFound(hit, "refractionRay(ray, hit)", caller);
    // hit.normal faces the incoming side: entering through the front face goes from air (1) into
    // the material (Ni), leaving through the back goes from Ni into air.
    const float eta = hit.frontFace ? 1.0f / hit.material.Ni : hit.material.Ni;
    const std::optional<Vec3> transmitted = refract(ray.direction, hit.normal, eta);
    if (!transmitted) return mirrorRay(ray, hit, caller);
    return {offsetRayOrigin(hit, *transmitted), *transmitted, RayKind::Specular};
}

Ray glossyRay(const Ray& ray, const Hit& hit, Vec3 lobeDirection, CallSite caller) {
    checkFound(hit, "glossyRay(ray, hit, d)", caller);
    const float length = std::sqrt(dot(lobeDirection, lobeDirection));
    PATHLAB_CHECK_CALLER(std::fabs(length - 1.0f) < 1e-3f, caller,
                         "glossyRay's d = " + vectorText(lobeDirection) +
                             " is not a direction (unit length): sampleLobe must return one");
    PATHLAB_CHECK_CALLER(lobeDirection.z >= 0.0f, caller,
                         "glossyRay's d = " + vectorText(lobeDirection) +
                             " points away from the lobe's axis (z < 0): sampleLobe's directions "
                             "have z = cos α >= 0");
    const Vec3 mirror = normalize(reflect(ray.direction, hit.normal));
    const Vec3 direction = normalize(OrthonormalBasis(mirror).toWorld(lobeDirection));
    return {offsetRayOrigin(hit, direction), direction, RayKind::Glossy};
}

Vec3 lobeFrameDirection(const Ray& ray, const Hit& hit, Vec3 worldDirection, CallSite caller) {
    checkFound(hit, "lobeFrameDirection(ray, hit, direction)", caller);
    const Vec3 mirror = normalize(reflect(ray.direction, hit.normal));
    return OrthonormalBasis(mirror).toLocal(worldDirection);
}

} // namespace pathlab
