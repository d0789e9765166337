// Cosine-weighted hemisphere sampling against its pdf, by a chi-square test.
#include "catch.h"
#include "statistics.h"

#include "pathlab/cosine_hemisphere.h"
#include "pathlab/support/pcg32.h"

#include <vector>

using namespace pathlab;

TEST_CASE("cosine hemisphere samples follow cos(theta)/pi (chi-square, alpha = 1e-4)",
          "[sampling]") {
    // Under pdf cosθ/π, cos²θ is uniform on [0,1] and φ uniform on [0,2π): equal-probability
    // bins are a grid in (cos²θ, φ). The test runs around a tilted normal, so the frame
    // construction is checked too.
    const Vec3 normal = normalize(Vec3{0.3f, -0.5f, 0.8f});
    const OrthonormalBasis frame(normal);
    constexpr int thetaBins = 10, phiBins = 20, samples = 400000;
    std::vector<int> counts(thetaBins * phiBins, 0);
    Pcg32 rng(42, 7);
    for (int i = 0; i < samples; ++i) {
        const Vec2 u{rng.nextFloat(), rng.nextFloat()};
        const Vec3 w = sampleCosineHemisphere(normal, u);
        REQUIRE(std::fabs(length(w) - 1.0f) < 1e-4f);
        const Vec3 local = frame.toLocal(w);
        REQUIRE(local.z >= 0.0f);
        const double cos2 = std::min(1.0, static_cast<double>(local.z) * local.z);
        double phi = std::atan2(local.y, local.x);
        if (phi < 0) phi += 2 * Pi;
        const int t = std::min(thetaBins - 1, static_cast<int>(cos2 * thetaBins));
        const int p = std::min(phiBins - 1, static_cast<int>(phi / (2 * Pi) * phiBins));
        ++counts[t * phiBins + p];
    }
    const double expected = static_cast<double>(samples) / counts.size();
    double chi2 = 0;
    for (int c : counts) chi2 += (c - expected) * (c - expected) / expected;
    const double critical = test::chiSquareCritical(static_cast<int>(counts.size()) - 1, 1e-4);
    INFO("chi-square " << chi2 << ", critical " << critical);
    CHECK(chi2 < critical);
}

TEST_CASE("a wrong sampler fails the same chi-square test (the test can fail)", "[sampling]") {
    // Uniform hemisphere sampling has cosθ (not cos²θ) uniform: the test must reject it.
    constexpr int thetaBins = 10, samples = 100000;
    std::vector<int> counts(thetaBins, 0);
    Pcg32 rng(1, 1);
    for (int i = 0; i < samples; ++i) {
        const double cosTheta = rng.nextFloat();
        ++counts[std::min(thetaBins - 1, static_cast<int>(cosTheta * cosTheta * thetaBins))];
    }
    const double expected = static_cast<double>(samples) / thetaBins;
    double chi2 = 0;
    for (int c : counts) chi2 += (c - expected) * (c - expected) / expected;
    CHECK(chi2 > test::chiSquareCritical(thetaBins - 1, 1e-4));
}

TEST_CASE("cosineHemispherePdf integrates to one over the hemisphere", "[sampling]") {
    // ∫ cosθ/π dω = ∫₀^{π/2} cosθ/π · 2π sinθ dθ, by the midpoint rule.
    double integral = 0;
    const int steps = 10000;
    for (int i = 0; i < steps; ++i) {
        const double theta = (i + 0.5) * (Pi / 2) / steps;
        integral += cosineHemispherePdf(static_cast<float>(std::cos(theta))) * 2 * Pi *
                    std::sin(theta) * (Pi / 2) / steps;
    }
    CHECK(integral == Approx(1.0).epsilon(1e-4));
    CHECK(cosineHemispherePdf(-0.5f) == 0.0f);
}
