#pragma once
/// The grader's statistics: Student's t, batch means, and Holm's step-down correction.

#include <vector>

namespace pathlab::grader {

/// Two-sided p-value of Student's t statistic with `dof` degrees of freedom.
double studentTwoSidedP(double t, double dof);

/// The two-sided critical value of Student's t at significance `alpha`.
double studentCritical(double alpha, double dof);

struct MeanEstimate {
    double mean = 0;
    double standardError = 0;
};

/// Mean and standard error of independent batch values (one per seed).
MeanEstimate batchMean(const std::vector<double>& values);

/// Holm's method: which of the hypotheses with p-values `p` are rejected, keeping the
/// family-wise error rate at `alpha`.
std::vector<bool> holmRejections(const std::vector<double>& p, double alpha);

} // namespace pathlab::grader
