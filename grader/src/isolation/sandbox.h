#pragma once
/// The sandbox submitted code is compiled and run in (grader batch): bubblewrap with no network,
/// the system read-only, nothing of the host but the files copied in, at neutral paths, and a
/// private, size-limited scratch folder whose files are handed back when the command ends. Its
/// first process is the grader's own (sandbox_init.cpp): it installs a seccomp filter that every
/// process inside inherits, and nothing of bubblewrap's or of the host's environment is inside.

#include "isolation/process_runner.h"

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace pathlab::grader {

/// Who runs sandboxed commands and where: shared by all commands of one submission.
struct SandboxPolicy {
    std::vector<int> cpus; ///< cores the commands may use (empty: any)
    /// When the grader runs as root, commands run as this otherwise unused user id, so that the
    /// process limit (which root ignores) holds and nothing runs as root. -1: as we are.
    int user = -1;
};

/// One command in the sandbox.
struct SandboxRun {
    std::vector<std::string> command; ///< argv, as seen inside
    /// Host path (a file, or a folder and every regular file below it, links not followed), path
    /// inside: copied in, read-only, so that no host path shows inside (not even in
    /// /proc/self/mountinfo).
    std::vector<std::pair<std::string, std::string>> files;
    /// Host file or folder, path inside: bound read-only as it is (links and all), its host path
    /// visible in mountinfo. Only for commands that run none of a submission's code (the
    /// intake's unpacker, which must see a submission's links to refuse them).
    std::vector<std::pair<std::string, std::string>> bound;
    std::vector<std::pair<std::string, std::string>> environment;
    std::vector<std::string> collect; ///< names in the scratch folder to hand back
    long long scratchBytes = 256LL << 20;
};

struct SandboxOutcome {
    ProcessOutcome process;
    std::map<std::string, std::string> files; ///< collected: name -> bytes
    std::string problem; ///< why the handed-back files could not be read (empty if fine)
};

/// Where a command in the sandbox starts, and where its files are collected from.
constexpr const char* SandboxScratch = "/scratch";

/// Runs `run` in the sandbox under `limits`. The tools (bwrap, the compiler) come from the system.
SandboxOutcome runInSandbox(const SandboxRun& run, const ProcessLimits& limits,
                            const SandboxPolicy& policy);

/// Whether bubblewrap can make a sandbox here; if not, why (for a one-line error).
std::string sandboxUnavailableReason();

/// A user id for the sandboxed commands of this process (see SandboxPolicy::user), or -1 when
/// not running as root.
int sandboxUserForThisProcess();

/// Ends every process left running as `user` (after a submission's last command).
void killProcessesOf(int user);

} // namespace pathlab::grader
