#pragma once
/// The submission viewer's last line of defence against a lab that forks or runs programs.

namespace pathlab {

/// Forbids this process (every thread of it) to create processes or to run programs from now
/// on: fork, vfork, clone without CLONE_THREAD and execve fail with EPERM; threads can still be
/// started. A seccomp filter, so it holds however the lab calls the kernel. Throws
/// std::runtime_error where the filter cannot be installed (then nothing may run).
void forbidNewProcesses();

} // namespace pathlab
