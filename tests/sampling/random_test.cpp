// PCG32 (the tests' generator) and the renderer's per-sample streams: reproducible, distinct
// for distinct keys, and uncorrelated between neighbouring pixels, samples, seeds and draws.
#include "catch.h"
#include "statistics.h"

#include "pathlab/render/path_driver.h"
#include "pathlab/support/pcg32.h"
#include "pathlab/random_stream.h"
#include "pathlab/render/triangle_sampling.h"

#include <array>
#include <cmath>
#include <functional>
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

TEST_CASE("SplitMix64 matches the reference implementation's first outputs", "[sampling][rng]") {
    // splitmix64.c (Vigna) seeded with 1234567 (its state is a stream's position): the first
    // five outputs, as Rosetta Code's SplitMix64 task lists them.
    RandomStream stream(1234567);
    const uint64_t expected[] = {6457827717110365317ull, 3203168211198807973ull,
                                 9817491932198370423ull, 4593380528125082431ull,
                                 16408922859458223821ull};
    for (uint64_t e : expected) CHECK(stream.nextUint64() == e);
}

TEST_CASE("a sample's stream started from its pixel's start is the one samplerFor gives",
          "[sampling][rng]") {
    const uint64_t start = PathDriver::pixelStreamStart(3, 777);
    for (uint64_t sample : {0ull, 1ull, 1000ull, 123456789ull}) {
        Sampler a = PathDriver::samplerFor(3, 777, sample);
        Sampler b = PathDriver::samplerAt(start, sample);
        for (int i = 0; i < 10; ++i) CHECK(a.get1D() == b.get1D());
    }
}

namespace {

/// Pearson's correlation of n pairs (x(i), y(i)).
double correlation(int n, const std::function<std::pair<float, float>(int)>& pairAt) {
    double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
    for (int i = 0; i < n; ++i) {
        const auto [x, y] = pairAt(i);
        sx += x, sy += y, sxx += double(x) * x, syy += double(y) * y, sxy += double(x) * y;
    }
    const double cov = sxy / n - (sx / n) * (sy / n);
    return cov / std::sqrt((sxx / n - (sx / n) * (sx / n)) * (syy / n - (sy / n) * (sy / n)));
}

/// The k-th number of a sample's stream.
float drawOf(uint64_t seed, uint64_t pixel, uint64_t sample, int k) {
    Sampler sampler = PathDriver::samplerFor(seed, pixel, sample);
    float u = 0;
    for (int i = 0; i <= k; ++i) u = sampler.get1D();
    return u;
}

/// Pearson's chi-square of n pairs binned on a 16 x 16 grid of the unit square.
double chiSquareOfPairs(int n, const std::function<std::pair<float, float>(int)>& pairAt) {
    std::array<int, 256> bins{};
    for (int i = 0; i < n; ++i) {
        const auto [x, y] = pairAt(i);
        ++bins[static_cast<size_t>(int(x * 16) * 16 + int(y * 16))];
    }
    const double expected = n / 256.0;
    double chi2 = 0;
    for (int count : bins) chi2 += (count - expected) * (count - expected) / expected;
    return chi2;
}

/// Pearson's chi-square of a 16 x 16 grid (255 degrees of freedom) exceeds this with probability
/// 1e-6 when the pairs are independent and uniform.
const double pairsCritical = test::chiSquareCritical(255, 1e-6);

} // namespace

TEST_CASE("neighbouring pixels', successive samples' and seeds' streams are uncorrelated",
          "[sampling][rng]") {
    // Pairs of streams whose keys differ by one (the cases a weak hash of the key would tie
    // together), compared draw by draw: draws 0-3 of one against draws 0-3 of the other. For
    // independent uniforms the correlation of n pairs has standard error 1/sqrt(n) = 0.0032;
    // 5 standard errors fail a correct generator with probability 5.7e-7 per pair of draws,
    // 1e-5 over the 16 below. The pairs of draws are also binned on a 16 x 16 grid: chi-square
    // with 255 degrees of freedom exceeds pairsCritical (376.6) with probability 1e-6.
    const int n = 100000;
    const double limit = 5.0 / std::sqrt(double(n));
    const uint64_t width = 512;
    struct Neighbour {
        const char* name;
        std::function<std::array<uint64_t, 3>(uint64_t)> other; // (seed, pixel, sample) of i's
    };
    const Neighbour neighbours[] = {
        {"the pixel to the right",
         [](uint64_t i) {
             return std::array<uint64_t, 3>{0, i + 1, 0};
         }},
        {"the pixel below",
         [&](uint64_t i) {
             return std::array<uint64_t, 3>{0, i + width, 0};
         }},
        {"the next sample",
         [](uint64_t i) {
             return std::array<uint64_t, 3>{0, i, 1};
         }},
        {"the next seed",
         [](uint64_t i) {
             return std::array<uint64_t, 3>{1, i, 0};
         }},
    };
    // (draw of pixel i, draw of its neighbour): the same draw, and the first against a later one.
    const std::pair<int, int> drawPairs[] = {{0, 0}, {3, 3}, {0, 3}, {3, 0}};
    for (const Neighbour& neighbour : neighbours) {
        for (const auto& [k, j] : drawPairs) {
            const auto pairAt = [&, k = k, j = j](int i) {
                const auto [seed, pixel, sample] = neighbour.other(uint64_t(i));
                return std::pair<float, float>{drawOf(0, uint64_t(i), 0, k),
                                               drawOf(seed, pixel, sample, j)};
            };
            INFO("draw " << k << " of a pixel's sample 0 at seed 0 against draw " << j << " of "
                         << neighbour.name);
            CHECK(std::fabs(correlation(n, pairAt)) < limit);
            CHECK(chiSquareOfPairs(n, pairAt) < pairsCritical);
        }
    }
}

TEST_CASE("the correlation checks notice streams that overlap or share their draws",
          "[sampling][rng]") {
    // The tests above can fail: pixels whose streams began one draw apart (a key of pixel·γ)
    // repeat each other's numbers, and a pair (u, 1 - u) fills only a diagonal of the grid.
    const int n = 100000;
    const auto overlapping = [](int i) {
        RandomStream pixel(uint64_t(i) * StreamGamma), next(uint64_t(i + 1) * StreamGamma);
        pixel.nextFloat();
        return std::pair<float, float>{pixel.nextFloat(), next.nextFloat()};
    };
    CHECK(correlation(n, overlapping) > 0.99);
    const auto mirrored = [](int i) {
        RandomStream stream{uint64_t(i)};
        const float u = stream.nextFloat();
        return std::pair<float, float>{u, 0.999999f - u};
    };
    CHECK(chiSquareOfPairs(n, mirrored) > pairsCritical);
}

TEST_CASE("successive draws of one sample are uncorrelated", "[sampling][rng]") {
    // As above: 5 standard errors of the correlation, chi-square on 255 degrees of freedom.
    const int n = 100000;
    for (int k = 0; k < 3; ++k) {
        const auto pairAt = [&](int i) {
            Sampler sampler = PathDriver::samplerFor(0, uint64_t(i), 0);
            for (int skip = 0; skip < k; ++skip) sampler.get1D();
            const float first = sampler.get1D();
            return std::pair<float, float>{first, sampler.get1D()};
        };
        INFO("draws " << k << " and " << k + 1);
        CHECK(std::fabs(correlation(n, pairAt)) < 5.0 / std::sqrt(double(n)));
        CHECK(chiSquareOfPairs(n, pairAt) < pairsCritical);
    }
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
