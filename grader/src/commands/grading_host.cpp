#include "commands/grading_host.h"

#include "isolation/sandbox.h"

#include "pathlab/support/input_error.h"
#include "pathlab/support/this_process.h"

namespace pathlab::grader {

LabBuild labBuildOfThisGrader() {
    return loadLabBuild((thisProgram().parent_path() / "lab_library_build.json").string());
}

void requireSandbox() {
    const std::string reason = sandboxUnavailableReason();
    if (!reason.empty()) throw InputError("the sandbox: " + reason);
}

} // namespace pathlab::grader
