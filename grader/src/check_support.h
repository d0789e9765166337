#pragma once
/// What the three checks of a lab share: each render's limits, their numbers in words, the median.

#include "grading.h"

#include <string>
#include <vector>

namespace pathlab::grader {

/// A number in the checks' sentences with `decimals` digits after the point, as printf's %.Nf
/// writes it: fixed(0.5, 2) is "0.50".
std::string fixed(double value, int decimals);

/// A number with `digits` significant digits, as printf's %.Ng writes it (no trailing zeros,
/// an exponent for large and small values): significant(1234.5, 3) is "1.23e+03".
std::string significant(double value, int digits);

/// Each render's limits: the rubric's, its time limit scaled to this machine (time_limit.h).
ProcessLimits limitsOf(const GraderSetup& setup);

/// The middle value (the upper one of an even count); 0 for none.
double median(std::vector<double> values);

/// Relative size of the float rounding between two renders of the same expectation at
/// different spp: a few parts in 1e7 of a float accumulation, bounded far below any bug's effect.
constexpr double floatRoundingFloor = 1e-5;

} // namespace pathlab::grader
