#pragma once
/// Why a Linux kernel may refuse bubblewrap its user namespaces, and what lets it.

#include <string>

namespace pathlab::grader {

/// The setting that keeps unprivileged user namespaces off on this kernel, with the exact command
/// (or AppArmor profile) that turns them on for bubblewrap; "" when no known setting forbids
/// them. Reads the kernel's settings under `procSys` (/proc/sys; another folder in the tests).
std::string userNamespaceRemedy(const std::string& procSys = "/proc/sys");

} // namespace pathlab::grader
