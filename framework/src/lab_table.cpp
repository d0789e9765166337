// Compiled once with the student's labs/ (PATHLAB_IMPL=student) and once with solutions/
// (PATHLAB_IMPL=solution): each set's explicit table of its four pathTrace functions.
// lab.h must come first: it names the lab namespaces after PATHLAB_IMPL (branching_student...).
#include "pathlab/lab.h"
#include "pathlab/lab_registry.h"
#include "pathlab/this_process.h"

namespace pathlab::PATHLAB_IMPL {

const LabTable& labTable() {
    // Same order as the Lab enum.
    static const LabTable table = {&branching::pathTrace, &uniform::pathTrace,
                                   &importance::pathTrace, &roulette::pathTrace};
    return table;
}

bool available() { return true; }

} // namespace pathlab::PATHLAB_IMPL

#ifdef PATHLAB_LAB_LIBRARY
// A submission compiled by the grader into a shared library exposes its table under this one
// unmangled name (the library is built with hidden visibility; this is its only export), for
// the submission viewer to find (apps/viewer/loaded_lab_table.cpp).
extern "C" PATHLAB_EXPORT const pathlab::LabTable* pathlab_lab_table() {
    return &pathlab::PATHLAB_IMPL::labTable();
}
#endif
