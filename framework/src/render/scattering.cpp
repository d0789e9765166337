#include "pathlab/scattering.h"

#include "pathlab/support/check.h"
#include "pathlab/cosine_hemisphere.h"
#include "pathlab/render/ray_origin.h"
#include "pathlab/render/specular.h"

namespace pathlab {

namespace {

/// The three bounces need a surface to leave: a missed hit has no position or normal.
void checkFound(const Hit& hit, const char* bounce, CallSite caller) {
    PATHLAB_CHECK_CALLER(hit.found, caller,
                         std::string(bounce) +
                             " needs a surface: bounce only after `if (!hit)` has returned "
                             "for a ray that left the scene");
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

} // namespace pathlab
