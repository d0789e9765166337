// The solution table of a build that has no solutions/: the student release, and the viewer
// that runs submitted labs (which must not hold the reference solutions its labs could call).
#include "runner/lab_tables.h"

#include "pathlab/support/input_error.h"

namespace pathlab::solution {

bool available() { return false; }

const LabTable& labTable() {
    throw InputError("the reference solutions are not part of this build (--solution needs the "
                     "instructor's build of PathLab)");
}

} // namespace pathlab::solution
