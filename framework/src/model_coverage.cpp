#include "pathlab/model_coverage.h"

#include "pathlab/constants.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace pathlab {

namespace {

// Enough to judge a view by: a 1M-triangle model is sampled one triangle in four.
constexpr size_t mostTrianglesDrawn = 250000;

struct ScreenPoint {
    float x, y; ///< in pixels, y down
};

float edge(const ScreenPoint& a, const ScreenPoint& b, float x, float y) {
    return (b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x);
}

} // namespace

double coveredShare(const Scene& scene, const CameraSettings& camera, float aspect, int columns) {
    const int rows = std::max(1, static_cast<int>(std::lround(columns / aspect)));
    const Vec3 forward = normalize(camera.lookAt - camera.position);
    const Vec3 right = normalize(cross(forward, camera.up));
    const Vec3 up = cross(right, forward);
    const float tanY = std::tan(0.5f * camera.fovDegrees * Pi / 180.0f);
    const float tanX = tanY * aspect;
    std::vector<char> covered(static_cast<size_t>(columns) * rows, 0);
    const size_t stride = std::max<size_t>(1, scene.triangles.size() / mostTrianglesDrawn);
    for (size_t t = 0; t < scene.triangles.size(); t += stride) {
        ScreenPoint corner[3];
        bool inFront = true;
        for (int k = 0; k < 3; ++k) {
            const Vec3 d = scene.positions[scene.triangles[t][k]] - camera.position;
            const float depth = dot(d, forward);
            if (depth <= 0) inFront = false;
            corner[k] = {(0.5f + 0.5f * dot(d, right) / (depth * tanX)) * columns,
                         (0.5f - 0.5f * dot(d, up) / (depth * tanY)) * rows};
        }
        if (!inFront) continue;
        const auto mark = [&](int x, int y) {
            if (x >= 0 && x < columns && y >= 0 && y < rows) covered[size_t(y) * columns + x] = 1;
        };
        mark(static_cast<int>(std::floor(corner[0].x)), static_cast<int>(std::floor(corner[0].y)));
        const float area = edge(corner[0], corner[1], corner[2].x, corner[2].y);
        if (area == 0) continue;
        const int x0 = std::max(
            0, static_cast<int>(std::floor(std::min({corner[0].x, corner[1].x, corner[2].x}))));
        const int x1 = std::min(
            columns - 1,
            static_cast<int>(std::ceil(std::max({corner[0].x, corner[1].x, corner[2].x}))));
        const int y0 = std::max(
            0, static_cast<int>(std::floor(std::min({corner[0].y, corner[1].y, corner[2].y}))));
        const int y1 = std::min(rows - 1, static_cast<int>(std::ceil(
                                              std::max({corner[0].y, corner[1].y, corner[2].y}))));
        for (int y = y0; y <= y1; ++y) {
            for (int x = x0; x <= x1; ++x) {
                const float cx = x + 0.5f, cy = y + 0.5f;
                // Inside when the centre is on the same side of all three edges as the triangle.
                const float w0 = edge(corner[1], corner[2], cx, cy) * area;
                const float w1 = edge(corner[2], corner[0], cx, cy) * area;
                const float w2 = edge(corner[0], corner[1], cx, cy) * area;
                if (w0 >= 0 && w1 >= 0 && w2 >= 0) mark(x, y);
            }
        }
    }
    const auto count = std::count(covered.begin(), covered.end(), 1);
    return static_cast<double>(count) / static_cast<double>(covered.size());
}

} // namespace pathlab
