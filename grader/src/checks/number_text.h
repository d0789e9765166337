#pragma once
/// Numbers in the checks' sentences, written as printf writes them in the "C" locale, whatever
/// the process's locale: feedback reads the same on every machine.

#include <string>

namespace pathlab::grader {

/// A number with `decimals` digits after the point, as printf's %.Nf writes it: fixed(0.5, 2)
/// is "0.50".
std::string fixed(double value, int decimals);

/// A number with `digits` significant digits, as printf's %.Ng writes it (no trailing zeros,
/// an exponent for large and small values): significant(1234.5, 3) is "1.23e+03".
std::string significant(double value, int digits);

} // namespace pathlab::grader
