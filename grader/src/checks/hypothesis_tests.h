#pragma once
/// The grader's hypothesis tests: Student's t (Boost.Math's), batch means, Welch's test and Holm's
/// step-down correction; and the median and float-rounding floor the checks compare with.

#include <vector>

namespace pathlab::grader {

/// Two-sided p-value of Student's t statistic with `dof` degrees of freedom (any dof > 0, not
/// only whole numbers: Welch's test makes fractional ones). Boost.Math's distribution.
double studentTwoSidedP(double t, double dof);

/// The two-sided critical value of Student's t at significance `alpha`.
double studentCritical(double alpha, double dof);

/// The one-sided critical value: P(T > value) = `alpha`.
double studentOneSidedCritical(double alpha, double dof);

struct MeanEstimate {
    double mean = 0;
    double standardError = 0;
};

/// Mean and standard error of independent batch values (one per seed).
MeanEstimate batchMean(const std::vector<double>& values);

/// Two-sided p-value of Welch's t-test that samples `a` and `b` (at least 2 values each) share
/// their mean. `standardErrorFloor` is added to the difference's standard error in quadrature,
/// for values that differ by rounding alone.
double welchTwoSidedP(const std::vector<double>& a, const std::vector<double>& b,
                      double standardErrorFloor = 0);

/// Holm's method: which of the hypotheses with p-values `p` are rejected, keeping the
/// family-wise error rate at `alpha`.
std::vector<bool> holmRejections(const std::vector<double>& p, double alpha);

/// The middle value (the upper one of an even count); 0 for none.
double median(std::vector<double> values);

/// exp(mean of the logarithms) of positive values; 0 for none.
double geometricMean(const std::vector<double>& values);

/// Relative size of the float rounding between two renders of the same expectation at
/// different spp: a few parts in 1e7 of a float accumulation, bounded far below any bug's effect.
constexpr double floatRoundingFloor = 1e-5;

} // namespace pathlab::grader
