#include "pathlab/scene_io/polygon_triangulation.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace pathlab {

namespace {

struct Point2 {
    double x, y;
};

/// (b - a) × (c - b): positive where the path a, b, c turns left.
double turn(const Point2& a, const Point2& b, const Point2& c) {
    return (b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x);
}

/// The polygon in the plane it lies nearest to, turned so that it runs counter-clockwise: its
/// normal by Newell's method, the two axes across it.
std::vector<Point2> flattened(const std::vector<Vec3>& points) {
    double n[3] = {0, 0, 0};
    for (size_t i = 0; i < points.size(); ++i) {
        const Vec3& a = points[i];
        const Vec3& b = points[(i + 1) % points.size()];
        n[0] += double(a.y - b.y) * double(a.z + b.z);
        n[1] += double(a.z - b.z) * double(a.x + b.x);
        n[2] += double(a.x - b.x) * double(a.y + b.y);
    }
    // Drop the axis the normal is most along: the polygon seen along it keeps most of its area,
    // and it runs counter-clockwise when that component of the normal is positive.
    int drop = 0;
    for (int k = 1; k < 3; ++k)
        if (std::abs(n[k]) > std::abs(n[drop])) drop = k;
    const int u = (drop + 1) % 3, v = (drop + 2) % 3;
    const double sign = n[drop] < 0 ? -1.0 : 1.0;
    std::vector<Point2> flat;
    flat.reserve(points.size());
    for (const Vec3& p : points) {
        const double c[3] = {p.x, p.y, p.z};
        flat.push_back({c[u], sign * c[v]});
    }
    return flat;
}

/// A length below which a turn counts as straight: rounding, not a corner.
double straightness(const std::vector<Point2>& flat) {
    double extent = 0;
    for (const Point2& p : flat) extent = std::max({extent, std::abs(p.x), std::abs(p.y)});
    return 1e-9 * extent * extent;
}

bool samePlace(const Point2& a, const Point2& b) { return a.x == b.x && a.y == b.y; }

/// Whether `p` keeps the triangle a, b, c (counter-clockwise) from being cut off as an ear: it
/// lies inside or on an edge. A corner at the very place of a, b or c does not: a polygon that
/// runs along a slit and back, as a ring drawn as one outline does, has such corners twice.
bool blocks(const Point2& p, const Point2& a, const Point2& b, const Point2& c) {
    if (samePlace(p, a) || samePlace(p, b) || samePlace(p, c)) return false;
    return turn(a, b, p) >= 0 && turn(b, c, p) >= 0 && turn(c, a, p) >= 0;
}

} // namespace

bool isConvexPolygon(const std::vector<Vec3>& points) {
    const std::vector<Point2> flat = flattened(points);
    const double tolerance = straightness(flat);
    const size_t n = flat.size();
    for (size_t i = 0; i < n; ++i)
        if (turn(flat[(i + n - 1) % n], flat[i], flat[(i + 1) % n]) < -tolerance) return false;
    return true;
}

std::optional<std::vector<std::array<size_t, 3>>> earClip(const std::vector<Vec3>& points) {
    const std::vector<Point2> flat = flattened(points);
    const double tolerance = straightness(flat);
    std::vector<size_t> left(points.size());
    for (size_t i = 0; i < left.size(); ++i) left[i] = i;
    std::vector<std::array<size_t, 3>> triangles;
    while (left.size() > 3) {
        bool cut = false;
        for (size_t k = 0; k < left.size() && !cut; ++k) {
            const size_t a = left[(k + left.size() - 1) % left.size()], b = left[k],
                         c = left[(k + 1) % left.size()];
            if (turn(flat[a], flat[b], flat[c]) <= tolerance) continue; // reflex or straight
            bool empty = true;
            for (const size_t other : left)
                if (other != a && other != b && other != c &&
                    blocks(flat[other], flat[a], flat[b], flat[c]))
                    empty = false;
            if (!empty) continue;
            triangles.push_back({a, b, c});
            left.erase(left.begin() + static_cast<std::ptrdiff_t>(k));
            cut = true;
        }
        if (!cut) return std::nullopt;
    }
    triangles.push_back({left[0], left[1], left[2]});
    return triangles;
}

} // namespace pathlab
