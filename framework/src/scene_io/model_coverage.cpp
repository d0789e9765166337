#include "pathlab/scene_io/model_coverage.h"

#include "pathlab/constants.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace pathlab {

namespace {

// Enough to judge a view by: a 1M-triangle model is sampled one triangle in four.
constexpr size_t mostTrianglesDrawn = 250000;

struct ScreenPoint {
    float x, y;     ///< in pixels, y down
    float inverseZ; ///< 1 / depth, which varies linearly across the image
};

float edge(const ScreenPoint& a, const ScreenPoint& b, float x, float y) {
    return (b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x);
}

/// The nearest surface seen through each pixel: its 1/depth (0 for none) and whether it shows
/// its front side.
class CoverageRaster {
public:
    CoverageRaster(int columns, int rows)
        : columns_(columns), rows_(rows), inverseZ_(size_t(columns) * rows, 0.0f),
          front_(size_t(columns) * rows, 0) {}

    void draw(const ScreenPoint (&corner)[3], bool front) {
        plot(static_cast<int>(std::floor(corner[0].x)), static_cast<int>(std::floor(corner[0].y)),
             corner[0].inverseZ, front);
        const float area = edge(corner[0], corner[1], corner[2].x, corner[2].y);
        if (area == 0) return;
        const auto [xLo, xHi] = std::minmax({corner[0].x, corner[1].x, corner[2].x});
        const auto [yLo, yHi] = std::minmax({corner[0].y, corner[1].y, corner[2].y});
        const int x0 = std::max(0, static_cast<int>(std::floor(xLo)));
        const int x1 = std::min(columns_ - 1, static_cast<int>(std::ceil(xHi)));
        const int y0 = std::max(0, static_cast<int>(std::floor(yLo)));
        const int y1 = std::min(rows_ - 1, static_cast<int>(std::ceil(yHi)));
        for (int y = y0; y <= y1; ++y) {
            for (int x = x0; x <= x1; ++x) {
                const float cx = x + 0.5f, cy = y + 0.5f;
                const float w0 = edge(corner[1], corner[2], cx, cy) / area;
                const float w1 = edge(corner[2], corner[0], cx, cy) / area;
                const float w2 = edge(corner[0], corner[1], cx, cy) / area;
                if (w0 < 0 || w1 < 0 || w2 < 0) continue; // the centre is outside
                plot(x, y,
                     w0 * corner[0].inverseZ + w1 * corner[1].inverseZ + w2 * corner[2].inverseZ,
                     front);
            }
        }
    }

    double frontShare() const {
        const auto count = std::count(front_.begin(), front_.end(), 1);
        return static_cast<double>(count) / static_cast<double>(front_.size());
    }

private:
    void plot(int x, int y, float inverseZ, bool front) {
        if (x < 0 || x >= columns_ || y < 0 || y >= rows_) return;
        const size_t i = size_t(y) * columns_ + x;
        if (inverseZ <= inverseZ_[i]) return; // farther than what the pixel shows
        inverseZ_[i] = inverseZ;
        front_[i] = front;
    }

    int columns_, rows_;
    std::vector<float> inverseZ_;
    std::vector<char> front_;
};

} // namespace

double coveredShare(const Scene& scene, const CameraSettings& camera, float aspect, int columns) {
    const int rows = std::max(1, static_cast<int>(std::lround(columns / aspect)));
    const Vec3 forward = normalize(camera.lookAt - camera.position);
    const Vec3 right = normalize(cross(forward, camera.up));
    const Vec3 up = cross(right, forward);
    const float tanY = std::tan(0.5f * camera.fovDegrees * Pi / 180.0f);
    const float tanX = tanY * aspect;
    CoverageRaster raster(columns, rows);
    const size_t stride = std::max<size_t>(1, scene.triangles.size() / mostTrianglesDrawn);
    for (size_t t = 0; t < scene.triangles.size(); t += stride) {
        const auto& triangle = scene.triangles[t];
        ScreenPoint corner[3];
        bool inFront = true;
        for (int k = 0; k < 3; ++k) {
            const Vec3 d = scene.positions[triangle[k]] - camera.position;
            const float depth = dot(d, forward);
            if (depth <= 0) inFront = false;
            corner[k] = {(0.5f + 0.5f * dot(d, right) / (depth * tanX)) * columns,
                         (0.5f - 0.5f * dot(d, up) / (depth * tanY)) * rows, 1.0f / depth};
        }
        if (!inFront) continue;
        const Vec3& a = scene.positions[triangle[0]];
        const Vec3 normal =
            cross(scene.positions[triangle[1]] - a, scene.positions[triangle[2]] - a);
        raster.draw(corner, dot(normal, camera.position - a) > 0);
    }
    return raster.frontShare();
}

} // namespace pathlab
