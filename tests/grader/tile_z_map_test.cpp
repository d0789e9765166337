// The HTML report's tile map (reports/tile_z_map.h): the correctness check's t and p shown on the
// normal scale, each tile where regionMeans puts its pixels, a correct lab's tiles pale.
#include "catch.h"

#include "checks/hypothesis_tests.h"
#include "reports/tile_z_map.h"

#include <cmath>

using namespace pathlab::grader;

TEST_CASE("a tile's z-score is its smallest p on the normal scale, signed like its t", "[grader]") {
    CHECK(zScoreOfP(0.05, 1.0) == Approx(1.959964).epsilon(1e-6));
    CHECK(zScoreOfP(0.05, -3.0) == Approx(-1.959964).epsilon(1e-6));
    CHECK(zScoreOfP(1.0, 0.0) == Approx(0.0).margin(1e-9));
    CHECK(zScoreOfP(0.0, 1.0) > tileZSaturation); // a region that cannot be noise saturates
    CHECK(std::isnan(zScoreOfP(NAN, 1.0)));

    // Whole image, then 2 x 2 tiles, three channels each; p from t as the check computes it.
    const std::vector<double> t = {0, 0, 0, 0.5, -1, 0.2, 6, 1, 1, -0.1, 0.1, 0, 0, -5, 0};
    std::vector<double> p;
    for (double v : t) p.push_back(studentTwoSidedP(v, 9));
    CHECK(tileZ(t, p, 0) == Approx(zScoreOfP(p[4], -1)));  // its green channel: p smallest
    CHECK(tileZ(t, p, 1) == Approx(zScoreOfP(p[6], 6)));   // red, too bright
    CHECK(tileZ(t, p, 3) == Approx(zScoreOfP(p[13], -5))); // green, too dark

    // 4 x 2 pixels: tile (column, row) = (x * 2 / 4, y * 2 / 2).
    const std::vector<unsigned char> rgb = tileZImage(t, p, 2, 4, 2);
    REQUIRE(rgb.size() == 4u * 2 * 3);
    const auto pixel = [&](int x, int y) { return &rgb[3 * (y * 4 + x)]; };
    CHECK((pixel(2, 0)[0] == 255 && pixel(2, 0)[1] < 64 && pixel(3, 0)[2] < 64));  // red tile 1
    CHECK((pixel(3, 1)[2] == 255 && pixel(2, 1)[0] < 64));                         // blue tile 3
    CHECK((pixel(0, 1)[0] > 240 && pixel(1, 1)[1] > 240 && pixel(0, 1)[2] > 240)); // pale tile 2
    CHECK(tileZImage(t, p, 3, 4, 2).empty()); // statistics of another tiling
}
