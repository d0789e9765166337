#pragma once
/// Seccomp filters: system calls the kernel refuses to this process and to every process it
/// starts from then on, however the call is made. Linux only: the grader's sandbox installs one
/// before anything of a submission runs, the submission viewer a stricter one before it loads a
/// submitted lab; a filter, once installed, cannot be removed, only narrowed by another.

#include <vector>

namespace pathlab {

/// A system call to refuse (its number, `__NR_...`), and the error it then fails with.
struct RefusedCall {
    long number;
    int error;
};

/// What a filter refuses. Calls of another architecture or ABI than this program's are refused
/// always: their numbers mean other calls.
struct SeccompRules {
    std::vector<RefusedCall> calls;
    /// No new processes: clone without CLONE_THREAD fails with EPERM (threads can still be
    /// started), and clone3, whose flags a filter cannot read, with ENOSYS, so that the C library
    /// falls back to clone.
    bool refuseNewProcesses = false;
};

/// Installs `rules` for every thread of this process, with no new privileges (a set-user-id
/// program cannot lift them). Throws std::runtime_error where the kernel refuses, saying why.
void installSeccompFilter(const SeccompRules& rules);

} // namespace pathlab
