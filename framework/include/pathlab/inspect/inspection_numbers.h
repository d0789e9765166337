#pragma once
/// How the path inspector writes its numbers and materials, in its table and its sentences.

#include "pathlab/material.h"

#include <string>

namespace pathlab {

/// Three significant digits, as printf's %.3g: "0.333", "2", "1.5e+03". Enough to tell a
/// weight of 3 from one of 2.97, few enough to read a path's column at a glance.
std::string threeDigits(double value);

/// A colour as one number when it is grey, else its three channels: "0.5", "0.8,0.1,0.1".
std::string compactColour(const Color& c);

/// A material by its components that are not black: "Kd 0.5 Ks 0.9", or "black".
std::string materialText(const Material& m);

} // namespace pathlab
