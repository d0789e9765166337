#pragma once
/// The four labs by name, and the table that maps each to its pathTrace.

#include "pathlab/color.h"
#include "pathlab/path_context.h"
#include "pathlab/ray.h"

#include <array>
#include <optional>
#include <string_view>

namespace pathlab {

/// The four exercises, in the order the handouts teach them.
enum class Lab { Branching, Uniform, Importance, Roulette };
constexpr std::array<Lab, 4> AllLabs = {Lab::Branching, Lab::Uniform, Lab::Importance,
                                        Lab::Roulette};

/// Whose code runs: the student's labs/ or the reference solutions/.
enum class Implementation { Student, Solution };

using PathTraceFunction = Color (*)(const Ray& ray, int depth, PathContext& ctx);
/// One implementation's pathTrace per lab, indexed by Lab.
using LabTable = std::array<PathTraceFunction, 4>;

/// "branching", "uniform", "importance", "roulette".
std::string_view labName(Lab lab);
std::optional<Lab> labFromName(std::string_view name);
/// "student" or "solution".
std::string_view implementationName(Implementation impl);
/// Labs 1–3 stop at maxDepth and estimate the same depth-limited image; lab 4 is unbiased.
constexpr bool isDepthLimited(Lab lab) { return lab != Lab::Roulette; }

// Each set of labs is a library built from labs/ or solutions/ plus lab_table.cpp, which
// defines its table explicitly (no static-initialiser registration, which a linker may drop).
// A build without solutions/ (the student release) has a solution table that is not available;
// the viewer that grades submissions loads its student table from the submission's library.
namespace student {
const LabTable& labTable();
bool available();
}
namespace solution {
/// Throws InputError when !available().
const LabTable& labTable();
bool available();
}

/// The pathTrace of `lab` in `impl`.
inline PathTraceFunction findPathTrace(Lab lab, Implementation impl) {
    const LabTable& table =
        impl == Implementation::Student ? student::labTable() : solution::labTable();
    return table[static_cast<int>(lab)];
}

} // namespace pathlab
