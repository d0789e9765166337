#include "checks/hypothesis_tests.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace pathlab::grader {

namespace {

/// The continued fraction of the regularised incomplete beta function (modified Lentz).
double betaContinuedFraction(double a, double b, double x) {
    const double tiny = 1e-300;
    double c = 1, d = 1 - (a + b) * x / (a + 1);
    d = 1 / (std::fabs(d) < tiny ? tiny : d);
    double h = d;
    for (int m = 1; m <= 300; ++m) {
        const double m2 = 2.0 * m;
        double numerator = m * (b - m) * x / ((a + m2 - 1) * (a + m2));
        for (int half = 0; half < 2; ++half) {
            d = 1 + numerator * d;
            d = 1 / (std::fabs(d) < tiny ? tiny : d);
            c = 1 + numerator / c;
            if (std::fabs(c) < tiny) c = tiny;
            const double delta = c * d;
            h *= delta;
            if (half == 1 && std::fabs(delta - 1) < 1e-15) return h;
            numerator = -(a + m) * (a + b + m) * x / ((a + m2) * (a + m2 + 1));
        }
    }
    return h;
}

/// I_x(a, b).
double regularizedIncompleteBeta(double a, double b, double x) {
    if (x <= 0) return 0;
    if (x >= 1) return 1;
    const double logFront =
        std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log1p(-x);
    if (x < (a + 1) / (a + b + 2)) return std::exp(logFront) * betaContinuedFraction(a, b, x) / a;
    return 1 - std::exp(logFront) * betaContinuedFraction(b, a, 1 - x) / b;
}

} // namespace

double studentTwoSidedP(double t, double dof) {
    if (!std::isfinite(t)) return 0;
    return regularizedIncompleteBeta(dof / 2, 0.5, dof / (dof + t * t));
}

double studentCritical(double alpha, double dof) {
    double lo = 0, hi = 1e3;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (studentTwoSidedP(mid, dof) > alpha ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

MeanEstimate batchMean(const std::vector<double>& values) {
    MeanEstimate e;
    const double n = static_cast<double>(values.size());
    if (values.empty()) return e;
    e.mean = std::accumulate(values.begin(), values.end(), 0.0) / n;
    if (values.size() < 2) return e;
    double squares = 0;
    for (double v : values) squares += (v - e.mean) * (v - e.mean);
    e.standardError = std::sqrt(squares / (n - 1) / n);
    return e;
}

double welchTwoSidedP(const std::vector<double>& a, const std::vector<double>& b,
                      double standardErrorFloor) {
    const MeanEstimate ma = batchMean(a), mb = batchMean(b);
    const double va = ma.standardError * ma.standardError, vb = mb.standardError * mb.standardError;
    const double se = std::sqrt(va + vb + standardErrorFloor * standardErrorFloor);
    if (se == 0) return ma.mean == mb.mean ? 1.0 : 0.0;
    // Welch–Satterthwaite degrees of freedom; the floor, which has no sampling noise, is left out.
    const double na = static_cast<double>(a.size()), nb = static_cast<double>(b.size());
    const double denominator = va * va / (na - 1) + vb * vb / (nb - 1);
    const double dof = denominator > 0 ? (va + vb) * (va + vb) / denominator : na + nb - 2;
    return studentTwoSidedP((ma.mean - mb.mean) / se, dof);
}

std::vector<bool> holmRejections(const std::vector<double>& p, double alpha) {
    std::vector<size_t> order(p.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return p[a] < p[b]; });
    std::vector<bool> rejected(p.size(), false);
    const double m = static_cast<double>(p.size());
    for (size_t rank = 0; rank < order.size(); ++rank) {
        if (p[order[rank]] > alpha / (m - static_cast<double>(rank))) break; // step down stops
        rejected[order[rank]] = true;
    }
    return rejected;
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values.empty() ? 0 : values[values.size() / 2];
}

} // namespace pathlab::grader
