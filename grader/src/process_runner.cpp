// POSIX: Linux and macOS (the grader is not built with MSVC). Pinning to cores is Linux only.
#include "process_runner.h"

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <grp.h>
#include <poll.h>
#if defined(__linux__)
#include <sched.h>
#endif
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace pathlab::grader {

std::string ProcessOutcome::describe() const {
    if (!started) return "could not be started";
    if (timedOut) {
        char limit[32];
        std::snprintf(limit, sizeof limit, "%.0f s", wallLimit);
        return std::string("did not finish within the time limit of ") + limit +
               " (an endless loop, or recursion that never ends?)";
    }
    if (signal != 0) {
        std::string name = strsignal(signal);
        std::string hint;
        if (signal == SIGSEGV)
            hint = ": often recursion without an end (the stack overflows) or a bad pointer";
        if (signal == SIGKILL) hint = ": killed: it used too much memory, or killed itself";
        if (signal == SIGABRT) hint = ": aborted, e.g. an uncaught exception or a failed assert";
        if (signal == SIGXCPU) hint = ": it used more CPU time than allowed";
        if (signal == SIGXFSZ) hint = ": it wrote a file larger than allowed";
        return "crashed (" + name + ", signal " + std::to_string(signal) + ")" + hint;
    }
    if (exitStatus != 0) {
        if (output.find("bad_alloc") != std::string::npos ||
            output.find("out of memory") != std::string::npos)
            return "ran out of memory (allocation failed under the memory limit)";
        return "exited with status " + std::to_string(exitStatus);
    }
    return "finished";
}

std::string ProcessOutcome::outputTail(int lines) const {
    std::vector<std::string> kept;
    size_t end = output.size();
    while (end > 0 && static_cast<int>(kept.size()) < lines) {
        const size_t start = output.rfind('\n', end - 1);
        const size_t from = start == std::string::npos ? 0 : start + 1;
        std::string line = output.substr(from, end - from);
        if (line.size() > 200) line = line.substr(0, 200) + "...";
        if (!line.empty()) kept.insert(kept.begin(), line);
        if (start == std::string::npos) break;
        end = start;
    }
    std::string tail;
    for (const std::string& line : kept) tail += (tail.empty() ? "" : "\n") + line;
    return tail;
}

namespace {

void setLimit(int resource, rlim_t value) {
    const rlimit limit{value, value};
    ::setrlimit(resource, &limit);
}

/// In the child, between fork and exec: only async-signal-safe calls.
[[noreturn]] void startChild(const std::vector<std::string>& argv, const ProcessLimits& limits,
                             const ProcessOptions& options, int outputFd, int collectFd) {
    // Its own process group, so that a timeout kills everything it started.
    ::setpgid(0, 0);
#ifndef PATHLAB_SANITIZED
    if (limits.memoryBytes > 0) setLimit(RLIMIT_AS, static_cast<rlim_t>(limits.memoryBytes));
#endif
    if (limits.cpuSeconds > 0) setLimit(RLIMIT_CPU, static_cast<rlim_t>(limits.cpuSeconds + 1));
    if (limits.fileBytes > 0) setLimit(RLIMIT_FSIZE, static_cast<rlim_t>(limits.fileBytes));
    if (limits.processes > 0) setLimit(RLIMIT_NPROC, static_cast<rlim_t>(limits.processes));
    setLimit(RLIMIT_CORE, 0);
#if defined(__linux__)
    if (!options.cpus.empty()) {
        cpu_set_t set;
        CPU_ZERO(&set);
        for (int cpu : options.cpus) CPU_SET(cpu, &set);
        ::sched_setaffinity(0, sizeof set, &set);
    }
#endif
    if (options.user >= 0) {
        const auto id = static_cast<uid_t>(options.user);
        if (::setgroups(0, nullptr) != 0 || ::setgid(id) != 0 || ::setuid(id) != 0) ::_exit(126);
    }
    ::dup2(outputFd, STDOUT_FILENO);
    ::dup2(outputFd, STDERR_FILENO);
    if (collectFd >= 0) {
        ::dup2(collectFd, 3); // dup2 clears close-on-exec on the copy
    }
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    ::execv(args[0], args.data());
    ::_exit(127);
}

/// Appends what is ready on `fd` to `text`, keeping at most `keep` bytes (the last ones when
/// `keepTail`, else the first, flagging `overflow`). False at end of file.
bool drain(int fd, std::string& text, size_t keep, bool keepTail, bool& overflow) {
    char buffer[65536];
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n <= 0) return false;
    if (keepTail) {
        text.append(buffer, static_cast<size_t>(n));
        if (text.size() > keep) text.erase(0, text.size() - keep);
    } else if (text.size() + static_cast<size_t>(n) > keep) {
        overflow = true;
    } else {
        text.append(buffer, static_cast<size_t>(n));
    }
    return true;
}

/// A pipe whose ends close in the children it is not handed to. Linux sets that atomically
/// (another thread may fork in between); macOS has no pipe2.
bool openPipe(int ends[2]) {
#if defined(__linux__)
    return ::pipe2(ends, O_CLOEXEC) == 0;
#else
    if (::pipe(ends) != 0) return false;
    ::fcntl(ends[0], F_SETFD, FD_CLOEXEC);
    ::fcntl(ends[1], F_SETFD, FD_CLOEXEC);
    return true;
#endif
}

} // namespace

ProcessOutcome runProcess(const std::vector<std::string>& argv, const ProcessLimits& limits,
                          const ProcessOptions& options) {
    ProcessOutcome outcome;
    outcome.wallLimit = limits.wallSeconds;
    int outputPipe[2], collectPipe[2] = {-1, -1};
    if (!openPipe(outputPipe)) return outcome;
    if (options.collectBytes > 0 && !openPipe(collectPipe)) {
        ::close(outputPipe[0]);
        ::close(outputPipe[1]);
        return outcome;
    }
    const auto start = std::chrono::steady_clock::now();
    const pid_t pid = ::fork();
    if (pid == 0) startChild(argv, limits, options, outputPipe[1], collectPipe[1]);
    ::close(outputPipe[1]);
    if (collectPipe[1] >= 0) ::close(collectPipe[1]);
    if (pid < 0) {
        ::close(outputPipe[0]);
        if (collectPipe[0] >= 0) ::close(collectPipe[0]);
        return outcome;
    }
    ::setpgid(pid, pid);
    outcome.started = true;

    auto elapsed = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    // Read both pipes until both close or time runs out.
    bool outputOpen = true, collectOpen = collectPipe[0] >= 0, ignored = false;
    while (outputOpen || collectOpen) {
        const double left = limits.wallSeconds - elapsed();
        if (left <= 0) {
            outcome.timedOut = true;
            ::kill(-pid, SIGKILL);
            break;
        }
        pollfd fds[2] = {{outputOpen ? outputPipe[0] : -1, POLLIN, 0},
                         {collectOpen ? collectPipe[0] : -1, POLLIN, 0}};
        if (::poll(fds, 2, static_cast<int>(std::min(left, 0.25) * 1000) + 1) <= 0) continue;
        if (fds[0].revents != 0)
            outputOpen = drain(outputPipe[0], outcome.output, 64u << 10, true, ignored);
        if (fds[1].revents != 0)
            collectOpen = drain(collectPipe[0], outcome.collected, options.collectBytes, false,
                                outcome.collectOverflow);
    }
    // The pipes closed (or we killed it): wait for the exit, still within the limit.
    int status = 0;
    while (true) {
        const pid_t done = ::waitpid(pid, &status, WNOHANG);
        if (done == pid) break;
        if (elapsed() > limits.wallSeconds) {
            outcome.timedOut = true;
            ::kill(-pid, SIGKILL);
            ::waitpid(pid, &status, 0);
            break;
        }
        ::usleep(2000);
    }
    ::kill(-pid, SIGKILL); // anything it left behind in its group
    ::close(outputPipe[0]);
    if (collectPipe[0] >= 0) ::close(collectPipe[0]);
    outcome.seconds = elapsed();
    if (WIFEXITED(status)) outcome.exitStatus = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) outcome.signal = WTERMSIG(status);
    if (outcome.timedOut) outcome.signal = 0;
    return outcome;
}

} // namespace pathlab::grader
