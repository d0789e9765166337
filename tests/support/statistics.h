#pragma once
/// Critical values for the tests' hypothesis tests, so each can state its significance level.

#include <cmath>

namespace pathlab::test {

/// The two-sided critical |z| of a standard normal at significance `alpha` (Acklam's rational
/// approximation of the quantile, relative error below 1.2e-9).
double normalCritical(double alpha);

/// The upper critical value of a chi-square with `dof` degrees of freedom at significance
/// `alpha` (Wilson–Hilferty approximation, accurate to well under 1% for dof >= 10).
inline double chiSquareCritical(int dof, double alpha) {
    const double k = dof;
    const double z = normalCritical(2 * alpha); // one-sided
    const double a = 2.0 / (9.0 * k);
    return k * std::pow(1.0 - a + z * std::sqrt(a), 3.0);
}

} // namespace pathlab::test
