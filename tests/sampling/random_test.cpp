// PCG32 and the per-sample streams: reproducible, and distinct for distinct keys.
#include "catch.h"

#include "pathlab/path_driver.h"
#include "pathlab/pcg32.h"
#include "pathlab/triangle_sampling.h"

#include <set>

using namespace pathlab;

TEST_CASE("PCG32 matches the reference implementation's first outputs", "[sampling][rng]") {
    // pcg32-demo from the PCG reference code: seed 42, sequence 54.
    Pcg32 rng(42u, 54u);
    const uint32_t expected[] = {0xa15c02b7, 0x7b47f409, 0xba1d3330,
                                 0x83d2f293, 0xbfa4784b, 0xcbed606e};
    for (uint32_t e : expected) CHECK(rng.nextUint() == e);
}

TEST_CASE("a sampler restarted with the same key repeats itself", "[sampling][rng]") {
    Sampler a = PathDriver::samplerFor(7, 1234, 5);
    Sampler b = PathDriver::samplerFor(7, 1234, 5);
    for (int i = 0; i < 100; ++i) CHECK(a.get1D() == b.get1D());
}

TEST_CASE("different seeds, pixels and samples give different streams", "[sampling][rng]") {
    std::set<float> firsts;
    for (uint64_t seed = 0; seed < 4; ++seed)
        for (uint64_t pixel = 0; pixel < 50; ++pixel)
            for (uint64_t sample = 0; sample < 50; ++sample)
                firsts.insert(PathDriver::samplerFor(seed, pixel, sample).get1D());
    // 10000 draws of 24-bit floats: a handful of collisions at most by chance, not thousands.
    CHECK(firsts.size() > 9990);
}

TEST_CASE("uniform floats lie in [0,1) with mean 1/2", "[sampling][rng]") {
    Pcg32 rng(3, 9);
    double sum = 0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        const float u = rng.nextFloat();
        REQUIRE(u >= 0.0f);
        REQUIRE(u < 1.0f);
        sum += u;
    }
    // Standard error of the mean: sqrt(1/12/n) = 6.5e-4; 5 SE is alpha ~ 6e-7.
    CHECK(std::fabs(sum / n - 0.5) < 5 * std::sqrt(1.0 / 12.0 / n));
}

TEST_CASE("uniform points on a triangle: inside it, centroid on average", "[sampling]") {
    const Vec3 a{0, 0, 0}, b{4, 0, 0}, c{0, 2, 0};
    Pcg32 rng(5, 5);
    Vec3 sum;
    const int n = 100000;
    for (int i = 0; i < n; ++i) {
        const Vec3 p = sampleTriangleUniform(a, b, c, {rng.nextFloat(), rng.nextFloat()});
        REQUIRE(p.x >= -1e-6f);
        REQUIRE(p.y >= -1e-6f);
        REQUIRE(p.x / 4 + p.y / 2 <= 1.0f + 1e-5f);
        sum += p;
    }
    // The centroid (4/3, 2/3); the x coordinate's SD is sqrt(8/9) ≈ 0.94, 5 SE ≈ 0.015.
    CHECK(sum.x / n == Approx(4.0 / 3.0).margin(0.015));
    CHECK(sum.y / n == Approx(2.0 / 3.0).margin(0.008));
    CHECK(triangleArea(a, b, c) == Approx(4.0f));
}
