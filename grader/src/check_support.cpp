#include "check_support.h"

#include <algorithm>
#include <cstdio>

namespace pathlab::grader {

std::string format(const char* pattern, double a, double b, double c, double d) {
    char text[256];
    std::snprintf(text, sizeof text, pattern, a, b, c, d);
    return text;
}

ProcessLimits limitsOf(const GraderSetup& setup) {
    return {setup.runSeconds > 0 ? setup.runSeconds : setup.rubric.secondsPerRun,
            setup.rubric.memoryBytes};
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values.empty() ? 0 : values[values.size() / 2];
}

} // namespace pathlab::grader
