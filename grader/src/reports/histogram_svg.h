#pragma once
/// A bar chart of fractions in tenths (0-9%, ..., 90-100%), as inline SVG for the grader's pages.

#include <array>
#include <string>

namespace pathlab::grader {

/// `bins[i]` bars, the count above each and its range below, `axisTitle` under them all; every
/// label inside the SVG's box, the tallest bar's count included.
std::string histogramSvg(const std::array<int, 10>& bins, const std::string& axisTitle);

} // namespace pathlab::grader
