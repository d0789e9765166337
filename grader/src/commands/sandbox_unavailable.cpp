// The sandbox where it cannot be built (macOS, and Linux with PATHLAB_SANDBOX=OFF): grading a
// student's own build works as everywhere; grading untrusted submissions says in one line that
// it needs Linux and bubblewrap.
#include "commands/commands.h"
#include "isolation/sandbox.h"

#include "pathlab/support/input_error.h"

namespace pathlab::grader {

namespace {

const char* const NeedsLinux =
    "needs Linux and bubblewrap (the sandbox that runs untrusted code), which this build does "
    "not have: grade submissions on a Linux machine (or in WSL2 on Windows); `grader` alone "
    "grades this build's own labs";

} // namespace

SandboxOutcome runInSandbox(const SandboxRun&, const ProcessLimits&, const SandboxPolicy&) {
    throw InputError(std::string("the sandbox ") + NeedsLinux);
}

std::string sandboxUnavailableReason() { return NeedsLinux; }

int sandboxUserForThisProcess() { return -1; }

void killProcessesOf(int) {}

int gradeOneSubmission(const Arguments&, const Rubric&, const std::string&) {
    throw InputError(std::string("grader submission ") + NeedsLinux);
}

int runBatch(const Arguments&, const Rubric&, const std::string&) {
    throw InputError(std::string("grader batch ") + NeedsLinux);
}

} // namespace pathlab::grader
