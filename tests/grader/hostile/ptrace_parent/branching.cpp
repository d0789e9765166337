// Hostile submission: tries to leave the submission viewer's seccomp filter through another
// process of its sandbox: attaching to it with ptrace, writing its memory through
// process_vm_writev and /proc/PID/mem; then starts a shell, which only an escape would allow.
// Every attempt is refused: the sandbox's first process is the grader's, not dumpable, and every
// process inside is under a filter that refuses ptrace and process_vm_*.
#include "pathlab/lab.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <string>
#include <sys/ptrace.h>
#include <sys/uio.h>
#include <unistd.h>

namespace pathlab::branching {

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    for (const pid_t target : {::getppid(), pid_t(1)}) {
        errno = 0;
        const long attached = ::ptrace(PTRACE_ATTACH, target, nullptr, nullptr);
        std::printf("ptrace %d: %s\n", static_cast<int>(target),
                    attached == 0 ? "ATTACHED" : std::strerror(errno));
        char byte = 0;
        iovec local{&byte, 1}, remote{reinterpret_cast<void*>(0x400000), 1};
        const ssize_t written = ::process_vm_writev(target, &local, 1, &remote, 1, 0);
        std::printf("process_vm_writev %d: %s\n", static_cast<int>(target),
                    written >= 0 ? "WROTE" : std::strerror(errno));
        const std::string mem = "/proc/" + std::to_string(target) + "/mem";
        const int fd = ::open(mem.c_str(), O_RDWR);
        std::printf("%s: %s\n", mem.c_str(), fd >= 0 ? "OPENED" : std::strerror(errno));
    }
    std::printf("shell: %s\n", std::system("echo ESCAPED") == 0 ? "ESCAPED" : std::strerror(errno));
    std::fflush(stdout);
    std::abort();
    (void)ray, (void)depth, (void)ctx;
}

} // namespace pathlab::branching
