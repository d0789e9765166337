#pragma once
/// A chi-square goodness-of-fit test of counts against their expectations, with the cells of
/// small expectation pooled so that the statistic follows its chi-square distribution.

#include <vector>

namespace pathlab {

struct ChiSquareFit {
    double statistic = 0;
    int cells = 0;            ///< compared, after pooling
    int degreesOfFreedom = 0; ///< cells − 1: the expectations' total is the counts' total
    double pValue = 1;        ///< of a statistic this large where the expectations are right
    /// Samples fell where nothing is expected (an expectation below 1e-9 of a sample): no
    /// statistic can excuse that, and pValue is 0.
    bool countsWhereNoneExpected = false;
};

/// Compares `observed` counts with `expected` ones cell by cell. Cells expecting fewer than
/// `minExpected` samples are pooled, the smallest first, into cells expecting at least that many
/// (the last pool joins the smallest cell above it if it stays short), as Mitsuba's chi2 test
/// does; Pearson's statistic over the pooled cells is referred to the chi-square distribution
/// (Boost.Math) for the p-value.
ChiSquareFit chiSquareFit(const std::vector<double>& observed, const std::vector<double>& expected,
                          double minExpected = 5);

/// The significance of each of `tests` independent tests that keeps the chance of any false
/// failure at `alpha` (Šidák): 1 − (1 − alpha)^(1/tests).
double sidakAlpha(double alpha, int tests);

} // namespace pathlab
