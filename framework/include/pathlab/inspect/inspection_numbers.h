#pragma once
/// How the path inspector writes its numbers, in its table and in its sentences alike.

#include <string>

namespace pathlab {

/// Three significant digits, as printf's %.3g: "0.333", "2", "1.5e+03". Enough to tell a
/// weight of 3 from one of 2.97, few enough to read a path's column at a glance.
std::string threeDigits(double value);

} // namespace pathlab
