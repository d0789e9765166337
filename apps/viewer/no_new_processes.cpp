#include "no_new_processes.h"

#include "process/seccomp_filter.h"

#include <cerrno>
#include <stdexcept>
#include <string>
#include <sys/syscall.h>

namespace pathlab {

void forbidNewProcesses() {
    SeccompRules rules;
#if defined(__x86_64__)
    rules.calls = {{__NR_fork, EPERM}, {__NR_vfork, EPERM}};
#endif
    rules.calls.insert(rules.calls.end(), {{__NR_execve, EPERM}, {__NR_execveat, EPERM}});
    rules.refuseNewProcesses = true;
    try {
        installSeccompFilter(rules);
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(std::string("cannot forbid new processes (") + e.what() + ")");
    }
}

} // namespace pathlab
