#include "checks/hypothesis_tests.h"

#include <boost/math/distributions/students_t.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace pathlab::grader {

double studentTwoSidedP(double t, double dof) {
    if (!std::isfinite(t)) return 0;
    if (!(dof > 0)) return 1;
    const boost::math::students_t distribution(dof);
    return std::min(1.0, 2 * cdf(complement(distribution, std::fabs(t))));
}

double studentCritical(double alpha, double dof) { return studentOneSidedCritical(alpha / 2, dof); }

double studentOneSidedCritical(double alpha, double dof) {
    const boost::math::students_t distribution(dof);
    return quantile(complement(distribution, alpha));
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

double geometricMean(const std::vector<double>& values) {
    if (values.empty()) return 0;
    double logs = 0;
    for (double v : values) logs += std::log(v);
    return std::exp(logs / static_cast<double>(values.size()));
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values.empty() ? 0 : values[values.size() / 2];
}

} // namespace pathlab::grader
