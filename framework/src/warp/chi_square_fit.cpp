#include "pathlab/warp/chi_square_fit.h"

#include <boost/math/distributions/chi_squared.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace pathlab {

namespace {

struct Cell {
    double observed = 0, expected = 0;
};

/// The cells in order of expectation, those below `minExpected` pooled from the smallest up.
std::vector<Cell> pooledCells(std::vector<Cell> cells, double minExpected) {
    std::sort(cells.begin(), cells.end(),
              [](const Cell& a, const Cell& b) { return a.expected < b.expected; });
    std::vector<Cell> pooled;
    Cell pool;
    for (const Cell& cell : cells) {
        if (cell.expected >= minExpected && pool.expected == 0) {
            pooled.push_back(cell);
            continue;
        }
        pool.observed += cell.observed;
        pool.expected += cell.expected;
        if (pool.expected >= minExpected) {
            pooled.push_back(pool);
            pool = {};
        }
    }
    if (pool.expected > 0 || pool.observed > 0) {
        if (pooled.empty()) {
            pooled.push_back(pool);
        } else { // too small alone: into the smallest cell above it
            pooled.front().observed += pool.observed;
            pooled.front().expected += pool.expected;
        }
    }
    return pooled;
}

} // namespace

ChiSquareFit chiSquareFit(const std::vector<double>& observed, const std::vector<double>& expected,
                          double minExpected) {
    ChiSquareFit fit;
    std::vector<Cell> cells;
    for (size_t i = 0; i < observed.size() && i < expected.size(); ++i) {
        if (expected[i] < 1e-9 && observed[i] > 0) fit.countsWhereNoneExpected = true;
        cells.push_back({observed[i], expected[i]});
    }
    const std::vector<Cell> pooled = pooledCells(std::move(cells), minExpected);
    fit.cells = static_cast<int>(pooled.size());
    fit.degreesOfFreedom = std::max(fit.cells - 1, 1);
    for (const Cell& cell : pooled)
        if (cell.expected > 0)
            fit.statistic +=
                (cell.observed - cell.expected) * (cell.observed - cell.expected) / cell.expected;
    fit.pValue = fit.countsWhereNoneExpected
                     ? 0
                     : boost::math::cdf(boost::math::complement(
                           boost::math::chi_squared(fit.degreesOfFreedom), fit.statistic));
    return fit;
}

double sidakAlpha(double alpha, int tests) {
    return 1 - std::pow(1 - alpha, 1.0 / std::max(tests, 1));
}

} // namespace pathlab
