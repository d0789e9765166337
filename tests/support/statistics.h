#pragma once
/// Critical values for the tests' hypothesis tests, so each can state its significance level:
/// Boost.Math's distributions, exact to double precision.

namespace pathlab::test {

/// The two-sided critical |z| of a standard normal at significance `alpha`.
double normalCritical(double alpha);

/// The upper critical value of a chi-square with `dof` degrees of freedom at significance
/// `alpha`: P(X > value) = alpha.
double chiSquareCritical(int dof, double alpha);

/// The upper tail of a chi-square with `dof` degrees of freedom at `statistic`: P(X > statistic).
double chiSquareUpperTail(int dof, double statistic);

} // namespace pathlab::test
