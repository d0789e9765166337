#pragma once
/// The tables that map each lab to its pathTrace, one per implementation.

#include "pathlab/render/lab_registry.h"
#include "pathlab/render/renderer.h"

#include <array>

namespace pathlab {

/// One implementation's pathTrace per lab, indexed by labIndex.
using LabTable = std::array<PathTraceFunction, LabCount>;

// Each set of labs is a library built from labs/ or solutions/ plus lab_table.cpp, which
// defines its table explicitly (no static-initialiser registration, which a linker may drop).
// A build without solutions/ (the student release) links no_solutions_table.cpp instead, and
// the viewer that grades submissions loads its student table from the submission's library.
// A program links pathlab_runner, then one student and one solution table.
namespace student {
const LabTable& labTable();
bool available();
} // namespace student
namespace solution {
/// Throws InputError when !available().
const LabTable& labTable();
bool available();
} // namespace solution

/// The pathTrace of `lab` in `impl`.
inline PathTraceFunction findPathTrace(Lab lab, Implementation impl) {
    const LabTable& table =
        impl == Implementation::Student ? student::labTable() : solution::labTable();
    return table[labIndex(lab)];
}

} // namespace pathlab
