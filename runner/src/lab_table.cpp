// Compiled into each set of labs (CMakeLists.txt, pathlab_lab_library): with the student's
// labs/ as PATHLAB_IMPL=student, with solutions/ as PATHLAB_IMPL=solution. The build defines
// each lab's name as that name with the set's appended (branching=branching_student ...), so the
// table below takes the set's own functions.
#include "runner/lab_tables.h"

#include "pathlab/lab.h"
#include "pathlab/support/this_process.h"

namespace pathlab::PATHLAB_IMPL {

const LabTable& labTable() {
    static const LabTable table = [] {
        LabTable t;
        t.pathTrace = {
#define PATHLAB_LAB_PATH_TRACE(name, Enumerator, depthLimited) &name::pathTrace,
            PATHLAB_FOR_EACH_LAB(PATHLAB_LAB_PATH_TRACE)
#undef PATHLAB_LAB_PATH_TRACE
        };
#define PATHLAB_LAB_LOBE(name, Enumerator)                                                         \
    t.lobe[labIndex(Lab::Enumerator)] = {&name::sampleLobe, &name::lobePdf};
        PATHLAB_FOR_EACH_LOBE_LAB(PATHLAB_LAB_LOBE)
#undef PATHLAB_LAB_LOBE
        return t;
    }();
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
