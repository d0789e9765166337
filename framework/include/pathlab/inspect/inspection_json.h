#pragma once
/// The path inspector's JSON (`viewer --inspect-out`, the grader's replay): a pixel's samples
/// through a lab and, when the reference replayed them too, its samples and the comparison.

#include "pathlab/inspect/inspected_path.h"
#include "pathlab/inspect/path_comparison.h"

#include <string>

namespace pathlab {

/// The JSON text of an inspection; `reference` and `comparison` are added when given.
std::string inspectionJson(const PixelInspection& lab, const PixelInspection* reference = nullptr,
                           const PathComparison* comparison = nullptr);

/// Reads the lab's inspection back from that text (the grader reads a submission's).
/// Throws InputError naming `source` when it is not one.
PixelInspection readInspectionJson(const std::string& text, const std::string& source);

} // namespace pathlab
