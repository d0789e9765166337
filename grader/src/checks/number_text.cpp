#include "checks/number_text.h"

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

} // namespace pathlab::grader
