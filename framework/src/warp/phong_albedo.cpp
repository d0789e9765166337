#include "pathlab/warp/phong_albedo.h"

#include <cmath>

namespace pathlab {

namespace {

constexpr double Pi = 3.14159265358979323846;

/// ∫₀^{2π} max(0, a − b·sin φ) dφ for b >= 0: over a whole turn where a >= b, nothing where
/// a <= −b, and between, the arc where a − b·sin φ is positive.
double positivePartOverTurn(double a, double b) {
    if (b <= std::fabs(a)) return a > 0 ? 2 * Pi * a : 0.0;
    return 2 * (a * (Pi / 2 + std::asin(a / b)) + std::sqrt(b * b - a * a));
}

} // namespace

double phongGlowReflectance(double exponent, double tiltRadians) {
    // In the lobe's frame a direction at (α, φ) has cos θ = cos α cos β − sin α sin β sin φ.
    constexpr int Steps = 20000; // even, for Simpson's rule
    const double h = (Pi / 2) / Steps;
    const double cosTilt = std::cos(tiltRadians), sinTilt = std::sin(tiltRadians);
    double sum = 0;
    for (int i = 0; i <= Steps; ++i) {
        const double alpha = i * h;
        const double weight = i == 0 || i == Steps ? 1 : i % 2 ? 4 : 2;
        const double c = std::cos(alpha), s = std::sin(alpha);
        sum += weight * std::pow(c, exponent) * s * positivePartOverTurn(c * cosTilt, s * sinTilt);
    }
    return sum * h / 3 * (exponent + 2) / (2 * Pi);
}

} // namespace pathlab
