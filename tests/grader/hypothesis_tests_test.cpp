// The grader's statistics against values computed independently: Student's t
// quantiles from printed tables, a Welch test worked by hand (and by numerical integration of
// the t density), and Holm's step-down on a small example.
#include "catch.h"

#include "checks/hypothesis_tests.h"

#include <cmath>

using namespace pathlab;
using namespace pathlab::grader;

TEST_CASE("Student's t p-values and critical values match the tables", "[grader]") {
    CHECK(studentTwoSidedP(2.228139, 10) == Approx(0.05).epsilon(1e-5));
    CHECK(studentTwoSidedP(-2.228139, 10) == Approx(0.05).epsilon(1e-5));
    CHECK(studentTwoSidedP(12.7062, 1) == Approx(0.05).epsilon(1e-4));
    CHECK(studentTwoSidedP(1.959964, 1e7) == Approx(0.05).epsilon(1e-5));
    CHECK(studentTwoSidedP(0, 9) == Approx(1.0));
    CHECK(studentTwoSidedP(INFINITY, 9) == 0);
    // The grader's own threshold: 10 seeds, alpha 1e-3.
    CHECK(studentCritical(1e-3, 9) == Approx(4.780913).epsilon(1e-5));
    // Far in the tail, where a search bounded at 1000 stopped: with one degree of freedom the
    // t distribution is Cauchy's, whose quantile is tan(pi (1/2 - alpha/2)) = 2/(pi alpha).
    CHECK(studentCritical(1e-9, 1) == Approx(2 / (M_PI * 1e-9)).epsilon(1e-6));
    CHECK(studentTwoSidedP(2e6, 1) == Approx(2 / (M_PI * 2e6)).epsilon(1e-6));
    // One-sided, from the tables: t(0.95, 4) = 2.131847, t(0.999, 9) = 4.296806.
    CHECK(studentOneSidedCritical(0.05, 4) == Approx(2.131847).epsilon(1e-6));
    CHECK(studentOneSidedCritical(1e-3, 9) == Approx(4.296806).epsilon(1e-6));
}

TEST_CASE("Welch's test gives the hand-worked p-value", "[grader]") {
    // Means 3 and 4.5, standard errors² 0.5 and 0.5833: t = -1.4412 on 8.989 degrees of freedom.
    CHECK(welchTwoSidedP({1, 2, 3, 4, 5}, {2, 3, 4, 5, 6, 7}) == Approx(0.18345).epsilon(1e-3));
    // Identical constant samples agree; constant samples that differ by rounding agree only
    // with a floor, and differ without one.
    CHECK(welchTwoSidedP({0.2, 0.2}, {0.2, 0.2}) == 1.0);
    CHECK(welchTwoSidedP({0.2000002, 0.2000002}, {0.2, 0.2}) == 0.0);
    CHECK(welchTwoSidedP({0.2000002, 0.2000002}, {0.2, 0.2}, 0.2 * 1e-5) > 0.5);
}

TEST_CASE("batch means give the mean and its standard error", "[grader]") {
    const MeanEstimate m = batchMean({1, 2, 3, 4});
    CHECK(m.mean == Approx(2.5));
    CHECK(m.standardError == Approx(std::sqrt(1.6666667 / 4)));
}

TEST_CASE("Holm's method steps down and stops at the first acceptance", "[grader]") {
    // Sorted: 0.005 <= 0.05/4, 0.01 <= 0.05/3, 0.03 > 0.05/2: stop; 0.04 is not rejected either
    // although it is below alpha.
    const std::vector<bool> rejected = holmRejections({0.01, 0.04, 0.03, 0.005}, 0.05);
    CHECK(rejected == std::vector<bool>{true, false, false, true});
    CHECK(holmRejections({0.5, 0.9}, 0.05) == std::vector<bool>{false, false});
}
