#pragma once
/// The tables that map each lab to its pathTrace, one per implementation.

#include "pathlab/render/lab_registry.h"
#include "pathlab/render/renderer.h"

#include <array>

namespace pathlab {

/// A glossy lobe's sampling routine and density, as a lab that writes them has them (handout
/// 05): a direction in the lobe's frame (z the lobe's axis) for two numbers in [0,1), and the
/// density per unit solid angle of a direction in that frame.
struct LobeRoutines {
    Vec3 (*sample)(Vec2 u, float exponent) = nullptr;
    float (*density)(Vec3 direction, float exponent) = nullptr;
    explicit operator bool() const { return sample && density; }
};

/// One implementation's functions per lab, indexed by labIndex: every lab's pathTrace, and the
/// lobe routines of the labs that write them (empty for the others).
struct LabTable {
    std::array<PathTraceFunction, LabCount> pathTrace{};
    std::array<LobeRoutines, LabCount> lobe{};
};

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
    return table.pathTrace[labIndex(lab)];
}

/// The lobe routines of `lab` in `impl`: empty for a lab that writes none.
inline LobeRoutines findLobeRoutines(Lab lab, Implementation impl) {
    const LabTable& table =
        impl == Implementation::Student ? student::labTable() : solution::labTable();
    return table.lobe[labIndex(lab)];
}

} // namespace pathlab
