// Hostile submission: the stub's one camera ray, and for the radiance a table of the tile means
// the kit ships (grader/references/*.json, the depth-limited images of the public scenes), the
// scene told by its camera and, where two scenes share one, by the material the camera ray hits;
// the furnaces' values at other depths from their formula. The array `tables` is filled in
// by batch_test.py. Every region's mean matches; the correctness check fails it because its
// images do not come from paths (checks/path_evidence.h): its pixels do not vary from seed to
// seed.
#include "pathlab/lab.h"

#include <algorithm>
#include <cmath>

namespace pathlab::branching {

namespace {

/// One public scene's camera and the means of the reference image's 4x4 tiles (row by row),
/// after the whole image's, per channel.
struct SceneTable {
    Vec3 position, lookAt, up;
    float fovDegrees;
    bool mirrorWalls; ///< the mirror furnace, whose camera is the furnace's
    bool furnace;     ///< a furnace of albedo (or mirror) 0.5 emitting 1, graded at other depths
    int maxDepth;     ///< the depth the means are of
    float means[17][3];
};

const SceneTable tables[] = {TILE_MEANS};

/// The tile (1 to 16) a camera ray of a square image passes through.
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

/// The table's colour for the camera ray `ray` (black where no table fits), and its hit.
Color tableColor(const Ray& ray, PathContext& ctx, Hit& hit) {
    hit = ctx.trace(ray);
    const bool mirror = hit && !isBlack(hit.material.Ks) && isBlack(hit.material.Kd);
    for (const SceneTable& t : tables) {
        if (length(ray.origin - t.position) > 1e-3f || (t.furnace && t.mirrorWalls != mirror))
            continue;
        const float* m = t.means[tileOf(t, ray.direction)];
        Color c(m[0], m[1], m[2]);
        // Both furnaces (albedo or mirror 0.5, emission 1) give sum over k <= maxDepth + 1 of
        // 0.5^k.
        if (t.furnace && ctx.maxDepth != t.maxDepth)
            c = Color(2.0f * (1.0f - std::pow(0.5f, static_cast<float>(ctx.maxDepth + 2))));
        return c;
    }
    return Color();
}

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    Hit hit;
    (void)depth;
    return tableColor(ray, ctx, hit);
}

} // namespace pathlab::branching
