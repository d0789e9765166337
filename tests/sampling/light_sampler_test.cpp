// The alias table picks each light in proportion to its power.
#include "catch.h"
#include "statistics.h"

#include "pathlab/constants.h"
#include "pathlab/render/light_sampler.h"
#include "pathlab/support/pcg32.h"

#include <vector>

using namespace pathlab;

TEST_CASE("lights are picked in proportion to power (chi-square, alpha = 1e-4)",
          "[sampling][lights]") {
    Scene scene;
    scene.pointLights = {{{0, 0, 0}, Color(1.0f)},
                         {{1, 0, 0}, Color(3.0f, 0.0f, 0.0f)},
                         {{2, 0, 0}, Color(0.0f)}}; // the dark one is never a light
    // One emissive triangle of area 2 and Ke 1: power π·2·1 against 4π·1 and 4π·1 above.
    scene.positions = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};
    scene.vertexNormals.resize(3);
    scene.triangles = {{0, 1, 2}};
    Material glow;
    glow.Ke = Color(1.0f);
    scene.triangleMaterials = {scene.addMaterial("glow", glow)};

    const LightSampler sampler(scene);
    REQUIRE(sampler.size() == 3);
    const double powers[] = {4 * Pi, 4 * Pi, 2 * Pi};
    const double total = 10 * Pi;
    for (size_t i = 0; i < 3; ++i) CHECK(sampler.pmf(i) == Approx(powers[i] / total));

    std::vector<int> counts(3, 0);
    Pcg32 rng(11, 3);
    const int n = 300000;
    for (int i = 0; i < n; ++i) {
        float pmf = 0;
        const LightSource& light = sampler.pick(rng.nextFloat(), rng.nextFloat(), pmf);
        const size_t index = light.type == LightSource::Type::Triangle ? 2 : light.index;
        REQUIRE(pmf == sampler.pmf(index));
        ++counts[index];
    }
    double chi2 = 0;
    for (size_t i = 0; i < 3; ++i) {
        const double expected = n * powers[i] / total;
        chi2 += (counts[i] - expected) * (counts[i] - expected) / expected;
    }
    // Two degrees of freedom: the exact critical value is -2 ln(alpha).
    CHECK(chi2 < -2 * std::log(1e-4));
}
