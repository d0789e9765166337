#pragma once
/// What the three checks of a lab share: each render's limits, number formatting, the median.

#include "grading.h"

#include <string>
#include <vector>

namespace pathlab::grader {

/// printf-style text of up to four numbers, for the checks' sentences.
std::string format(const char* pattern, double a, double b = 0, double c = 0, double d = 0);

/// Each render's limits: the rubric's, its time limit scaled to this machine (time_limit.h).
ProcessLimits limitsOf(const GraderSetup& setup);

/// The middle value (the upper one of an even count); 0 for none.
double median(std::vector<double> values);

/// Relative size of the float rounding between two renders of the same expectation at
/// different spp: a few parts in 1e7 of a float accumulation, bounded far below any bug's effect.
constexpr double floatRoundingFloor = 1e-5;

} // namespace pathlab::grader
