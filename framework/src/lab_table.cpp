// Compiled once with the student's labs/ (PATHLAB_IMPL=student) and once with solutions/
// (PATHLAB_IMPL=solution): each set's explicit table of its four pathTrace functions.
// lab.h must come first: it opens the inline namespace PATHLAB_IMPL that the labs live in.
#include "pathlab/lab.h"
#include "pathlab/lab_registry.h"

namespace pathlab::PATHLAB_IMPL {

const LabTable& labTable() {
    // Same order as the Lab enum.
    static const LabTable table = {&branching::pathTrace, &uniform::pathTrace,
                                   &importance::pathTrace, &roulette::pathTrace};
    return table;
}

} // namespace pathlab::PATHLAB_IMPL
