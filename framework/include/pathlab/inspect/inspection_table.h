#pragma once
/// The path inspector as text: one table per sample, a row per vertex (`make inspect`,
/// `viewer --inspect` without --inspect-out).

#include "pathlab/inspect/inspected_path.h"

#include <string>

namespace pathlab {

std::string inspectionTable(const PixelInspection& inspection);

} // namespace pathlab
