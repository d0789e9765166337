#include "statistics.h"

#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/normal.hpp>

namespace pathlab::test {

double normalCritical(double alpha) {
    return quantile(complement(boost::math::normal_distribution<double>(), alpha / 2));
}

double chiSquareCritical(int dof, double alpha) {
    return quantile(complement(boost::math::chi_squared_distribution<double>(dof), alpha));
}

double chiSquareUpperTail(int dof, double statistic) {
    return cdf(complement(boost::math::chi_squared_distribution<double>(dof), statistic));
}

} // namespace pathlab::test
