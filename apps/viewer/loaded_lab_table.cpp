// The student labs of the submission viewer (viewer-submission): not linked in, but loaded from
// the shared library that `grader batch` compiled from a submission, named by the environment
// variable PATHLAB_LABS_LIBRARY. Before the library's first line runs, the process loses the
// right to start processes or programs (no_new_processes.h), and ignores SIGPIPE.
#include "no_new_processes.h"

#include "runner/lab_tables.h"

#include "pathlab/support/input_error.h"
#include "pathlab/support/this_process.h"

#include <csignal>
#include <cstdlib>
#include <string>

namespace pathlab::student {

namespace {

LabTable load() {
    const char* path = std::getenv("PATHLAB_LABS_LIBRARY");
    if (!path || !*path)
        throw InputError("PATHLAB_LABS_LIBRARY is not set: this viewer runs a submission's labs, "
                         "compiled into a shared library by `grader batch`");
    forbidNewProcesses();
    // The grader stops reading a render's output past a limit: a lab that prints on then gets
    // EPIPE, not a signal that ends the render.
    std::signal(SIGPIPE, SIG_IGN);
    std::string why;
    using Entry = const LabTable* (*)();
    const auto entry = reinterpret_cast<Entry>(findLibrarySymbol(path, "pathlab_lab_table", why));
    if (!entry) throw InputError(std::string("cannot load the labs from ") + path + ": " + why);
    return *entry();
}

} // namespace

bool available() { return true; }

const LabTable& labTable() {
    static const LabTable table = load();
    return table;
}

} // namespace pathlab::student
