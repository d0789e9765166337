// The polynomial sine and cosine cosine sampling uses, against the C library's in double.
#include "catch.h"

#include "pathlab/constants.h"
#include "pathlab/small_angle_sin_cos.h"

#include <algorithm>
#include <cmath>

using namespace pathlab;

TEST_CASE("sinCosSmallAngle is within 2.5e-7 of sin and cos on [-pi/4, pi/4]", "[sampling]") {
    // Near 0.7 a float's ulp is 6e-8: the bound is 4 ulp. A sine series one term shorter (to
    // x^7) errs by 3.1e-7 at pi/4 and fails it.
    constexpr int steps = 1 << 20;
    double worstSin = 0, worstCos = 0;
    for (int i = 0; i <= steps; ++i) {
        const float x = static_cast<float>((2.0 * i / steps - 1.0) * (Pi / 4));
        const SinCos value = sinCosSmallAngle(x);
        worstSin = std::max(worstSin, std::fabs(value.sin - std::sin(static_cast<double>(x))));
        worstCos = std::max(worstCos, std::fabs(value.cos - std::cos(static_cast<double>(x))));
    }
    INFO("largest error: sine " << worstSin << ", cosine " << worstCos);
    CHECK(worstSin < 2.5e-7);
    CHECK(worstCos < 2.5e-7);
}

TEST_CASE("sinCosSmallAngle is exact at 0 and odd and even in x", "[sampling]") {
    CHECK(sinCosSmallAngle(0.0f).sin == 0.0f);
    CHECK(sinCosSmallAngle(0.0f).cos == 1.0f);
    for (const float x : {0.1f, 0.5f, 0.785f}) {
        CHECK(sinCosSmallAngle(-x).sin == -sinCosSmallAngle(x).sin);
        CHECK(sinCosSmallAngle(-x).cos == sinCosSmallAngle(x).cos);
    }
}
