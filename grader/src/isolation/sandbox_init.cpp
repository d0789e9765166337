// pathlab-sandbox-init: the first process of the grader's sandbox (pid 1 there: bubblewrap starts
// it with --as-pid-1, so no process of bubblewrap's is inside).
//
//     pathlab-sandbox-init NAME... -- COMMAND [ARG...]
//
// It makes itself unreadable to the sandbox's other processes (not dumpable: no ptrace, no
// /proc/1/mem, no /proc/1/environ), installs the sandbox's seccomp filter, which COMMAND and
// everything COMMAND starts inherit, runs COMMAND without file descriptor 3, and waits for every
// process of the sandbox. On descriptor 3 it then hands the grader how COMMAND ended, as a line
// "ended exit N", "ended signal N" or "ended stopped N" (COMMAND stopped itself with signal N,
// and was killed), followed by each NAME that COMMAND left in the working folder as a regular
// file: a line "NAME SIZE", then SIZE bytes. It exits 0, or 125 when it could not do its part.
//
// Its own code is all there is of the grader inside: no shell, no helper left unfiltered for a
// submission to take over (grader/src/isolation/README.md).
#include "process/seccomp_filter.h"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <stdexcept>
#include <string>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace {

using pathlab::RefusedCall;

/// What no process of the sandbox may do. Nothing the grader runs there (the compiler, the
/// unpacker, the viewer, TBB, ThreadSanitizer) needs these; a submission would use them to reach
/// other processes (ptrace, reading or writing another's memory: the way out of the submission
/// viewer's stricter filter), to leave the core its timed runs were given, or to reach kernel
/// interfaces a lab has no use for. They fail with EPERM.
std::vector<RefusedCall> sandboxRefusals() {
    std::vector<long> calls = {
        __NR_ptrace,
        __NR_process_vm_readv,
        __NR_process_vm_writev,
        __NR_kcmp,
        __NR_sched_setaffinity,
        __NR_perf_event_open,
        __NR_bpf,
        __NR_userfaultfd,
        __NR_io_uring_setup,
        __NR_io_uring_enter,
        __NR_io_uring_register,
        __NR_keyctl,
        __NR_add_key,
        __NR_request_key,
        __NR_unshare,
        __NR_setns,
        __NR_mount,
        __NR_umount2,
        __NR_pivot_root,
        __NR_chroot,
        __NR_pidfd_getfd,
        __NR_pidfd_open,
        __NR_open_tree,
        __NR_move_mount,
        __NR_fsopen,
        __NR_fsmount,
        __NR_fsconfig,
        __NR_fspick,
    };
    std::vector<RefusedCall> refused;
    for (long call : calls) refused.push_back({call, EPERM});
    return refused;
}

/// Writes all of `size` bytes, or fails.
bool writeAll(int fd, const char* data, size_t size) {
    while (size > 0) {
        const ssize_t n = ::write(fd, data, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        data += n;
        size -= static_cast<size_t>(n);
    }
    return true;
}

bool writeLine(int fd, const std::string& line) { return writeAll(fd, line.data(), line.size()); }

/// Hands back `name` if it is a regular file of the working folder (never a link's target).
bool handBack(int out, const std::string& name) {
    const int fd = ::open(name.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) return true;
    struct stat info {};
    if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
        ::close(fd);
        return true;
    }
    bool ok = writeLine(out, name + " " + std::to_string(info.st_size) + "\n");
    char buffer[65536];
    for (off_t left = info.st_size; ok && left > 0;) {
        const ssize_t n =
            ::read(fd, buffer, static_cast<size_t>(std::min<off_t>(left, sizeof buffer)));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break; // shorter than announced: the grader says so
        ok = writeAll(out, buffer, static_cast<size_t>(n));
        left -= n;
    }
    ::close(fd);
    return ok;
}

/// Runs the command and waits for every process of the sandbox; returns how the command ended.
std::string runCommand(char** command) {
    const pid_t child = ::fork();
    if (child < 0) return "ended unstarted " + std::to_string(errno);
    if (child == 0) {
        ::close(3);
        ::execv(command[0], command);
        std::fprintf(stderr, "sandbox: cannot run %s: %s\n", command[0], std::strerror(errno));
        ::_exit(127);
    }
    std::string ended;
    for (;;) {
        int status = 0;
        const pid_t pid = ::waitpid(-1, &status, WUNTRACED);
        if (pid < 0 && errno == EINTR) continue;
        if (pid < 0) break; // no process left
        if (pid != child) continue;
        if (WIFSTOPPED(status)) {
            // Stopped, it would only wait for the grader's time limit: said as what it did.
            if (ended.empty()) ended = "ended stopped " + std::to_string(WSTOPSIG(status));
            ::kill(child, SIGKILL);
            continue;
        }
        if (ended.empty())
            ended = WIFEXITED(status) ? "ended exit " + std::to_string(WEXITSTATUS(status))
                                      : "ended signal " + std::to_string(WTERMSIG(status));
        // The command is over: whatever it left running goes (pid 1 signals all but itself).
        ::kill(-1, SIGKILL);
    }
    return ended;
}

} // namespace

int main(int argc, char** argv) {
    int separator = 1;
    while (separator < argc && std::strcmp(argv[separator], "--") != 0) ++separator;
    if (separator + 1 >= argc) {
        std::fprintf(stderr, "usage: pathlab-sandbox-init NAME... -- COMMAND [ARG...]\n");
        return 125;
    }
    if (::prctl(PR_SET_DUMPABLE, 0, 0, 0, 0) != 0) {
        std::fprintf(stderr, "sandbox: cannot make its first process undumpable: %s\n",
                     std::strerror(errno));
        return 125;
    }
    try {
        pathlab::installSeccompFilter({sandboxRefusals(), false});
    } catch (const std::runtime_error& e) {
        std::fprintf(stderr, "sandbox: cannot install its filter (%s)\n", e.what());
        return 125;
    }
    const std::string ended = runCommand(argv + separator + 1);
    if (!writeLine(3, ended + "\n")) return 125;
    for (int i = 1; i < separator; ++i)
        if (!handBack(3, argv[i])) return 125;
    return 0;
}
