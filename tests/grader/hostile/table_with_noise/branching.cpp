// Hostile submission: the table of tile means of table_of_tile_means, with what a check of
// variance and of bounce rays would look for added: noise of mean zero on every sample, and one
// diffuse bounce ray traced and thrown away. Every region's mean still matches; the correctness
// check fails it because inside each tile its image is flat where the reference image shows the
// scene (checks/path_evidence.h).
#include "pathlab/lab.h"

#include <algorithm>
#include <cmath>

namespace pathlab::branching {

namespace {

struct SceneTable {
    Vec3 position, lookAt, up;
    float fovDegrees;
    bool mirrorWalls;
    bool furnace;
    int maxDepth;
    float means[17][3];
};

const SceneTable tables[] = {TILE_MEANS};

int tileOf(const SceneTable& t, const Vec3& direction) {
    const Vec3 forward = normalize(t.lookAt - t.position);
    const Vec3 right = normalize(cross(forward, t.up));
    const Vec3 up = cross(right, forward);
    const float half = std::tan(0.5f * t.fovDegrees * Pi / 180.0f);
    const float along = dot(direction, forward);
    const float x = 0.5f * (dot(direction, right) / along / half + 1.0f);
    const float y = 0.5f * (1.0f - dot(direction, up) / along / half);
    return 1 + std::clamp(static_cast<int>(y * 4), 0, 3) * 4 +
           std::clamp(static_cast<int>(x * 4), 0, 3);
}

} // namespace

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    (void)depth;
    const Hit hit = ctx.trace(ray);
    const bool mirror = hit && !isBlack(hit.material.Ks) && isBlack(hit.material.Kd);
    // The bounce ray that a count of rays would miss.
    if (hit && !isBlack(hit.material.Kd)) (void)ctx.trace(diffuseRay(hit, ctx.sampler.get2D()));
    for (const SceneTable& t : tables) {
        if (length(ray.origin - t.position) > 1e-3f || (t.furnace && t.mirrorWalls != mirror))
            continue;
        const float* m = t.means[tileOf(t, ray.direction)];
        Color c(m[0], m[1], m[2]);
        if (t.furnace && ctx.maxDepth != t.maxDepth)
            c = Color(2.0f * (1.0f - std::pow(0.5f, static_cast<float>(ctx.maxDepth + 2))));
        // Noise of mean zero: the pixels vary from seed to seed as a rendered image's do.
        return c * (1.0f + 1.6f * (ctx.sampler.get1D() - 0.5f));
    }
    return Color();
}

} // namespace pathlab::branching
