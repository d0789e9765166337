#include "check_support.h"

#include <algorithm>
#include <iomanip>
#include <locale>
#include <sstream>

namespace pathlab::grader {

namespace {

/// A stream that writes numbers as printf does in the "C" locale, whatever the global one.
std::ostringstream numberStream() {
    std::ostringstream out;
    out.imbue(std::locale::classic());
    return out;
}

} // namespace

std::string fixed(double value, int decimals) {
    std::ostringstream out = numberStream();
    out << std::fixed << std::setprecision(decimals) << value;
    return out.str();
}

// A stream with no floatfield set writes as %g does, with its precision as the digits.
std::string significant(double value, int digits) {
    std::ostringstream out = numberStream();
    out << std::setprecision(digits) << value;
    return out.str();
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
