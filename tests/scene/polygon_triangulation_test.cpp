// Concave OBJ faces are cut into triangles that cover the face and nothing more.
#include "catch.h"
#include "test_support.h"

#include "pathlab/scene_io/obj_loader.h"
#include "pathlab/scene_io/polygon_triangulation.h"
#include "pathlab/scene_io/scene.h"

#include <fstream>

using namespace pathlab;

namespace {

/// An L of area 3 in the plane z = 0, counter-clockwise seen from +z: the unit squares
/// [0,2]x[0,1] and [0,1]x[1,2]; its notch [1,2]x[1,2] is not part of it.
const std::vector<Vec3> lShape = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};

float area(const Vec3& a, const Vec3& b, const Vec3& c) { return 0.5f * cross(b - a, c - a).z; }

bool inNotch(const Vec3& p) { return p.x > 1 && p.y > 1; }

} // namespace

TEST_CASE("convex and concave polygons are told apart, in any plane and either way round",
          "[scene]") {
    CHECK(isConvexPolygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}));
    CHECK(isConvexPolygon({{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}}));            // clockwise
    CHECK(isConvexPolygon({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}})); // straight
    CHECK(!isConvexPolygon(lShape));
    std::vector<Vec3> tilted; // the L in the plane x = y, seen from the side
    for (const Vec3& p : lShape) tilted.push_back({p.x, p.x, p.y});
    CHECK(!isConvexPolygon(tilted));
}

TEST_CASE("ear clipping covers a concave polygon exactly, keeping its front side", "[scene]") {
    for (const bool reversed : {false, true}) {
        std::vector<Vec3> points = lShape;
        if (reversed) points.assign(lShape.rbegin(), lShape.rend());
        const auto triangles = earClip(points);
        REQUIRE(triangles.has_value());
        CHECK(triangles->size() == 4);
        float total = 0;
        for (const auto& t : *triangles) {
            const float a = area(points[t[0]], points[t[1]], points[t[2]]);
            // Every triangle turns the way the polygon does: clockwise ones have negative area.
            CHECK((reversed ? -a : a) > 0);
            total += a;
            const Vec3 centroid = (points[t[0]] + points[t[1]] + points[t[2]]) * (1.0f / 3);
            CHECK(!inNotch(centroid));
        }
        CHECK(std::abs(total) == Approx(3));
    }
    // A bow tie crosses itself: no ear to cut.
    CHECK(!earClip({{0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}}).has_value());
}

TEST_CASE("a concave OBJ face is cut by PathLab, a convex one as tinyobjloader cuts it",
          "[scene][obj-leniency]") {
    const std::string dir = test::temporaryFolder("concave");
    std::ofstream(dir + "/a.obj") << "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\n"
                                     "f 1 2 3 4 5 6\n"
                                     "v 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\nf -4 -3 -2 -1\n";
    Scene scene;
    loadObj(dir + "/a.obj", scene);
    REQUIRE(scene.triangles.size() == 6);
    float lArea = 0;
    for (size_t t = 0; t < 4; ++t) {
        const auto& tri = scene.triangles[t];
        const Vec3 &a = scene.positions[tri[0]], &b = scene.positions[tri[1]],
                   &c = scene.positions[tri[2]];
        CHECK(a.z == 0);
        CHECK(area(a, b, c) > 0);
        CHECK(!inNotch((a + b + c) * (1.0f / 3)));
        lArea += area(a, b, c);
    }
    CHECK(lArea == Approx(3));
    // The convex square: tinyobjloader's two triangles, along its shorter diagonal.
    CHECK(scene.positions[scene.triangles[4][0]].z == 1);
    CHECK(area(scene.positions[scene.triangles[4][0]], scene.positions[scene.triangles[4][1]],
               scene.positions[scene.triangles[4][2]]) == Approx(0.5));
}
