#include "process_runner.h"

#include <chrono>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace pathlab::grader {

std::string ProcessOutcome::describe() const {
    if (!started) return "could not be started";
    if (timedOut) return "did not finish within the time limit (an endless loop, or recursion "
                         "that never ends?)";
    if (signal != 0) {
        std::string name = strsignal(signal);
        std::string hint;
        if (signal == SIGSEGV)
            hint = ": often recursion without an end (the stack overflows) or a bad pointer";
        if (signal == SIGKILL) hint = ": killed, usually for using too much memory";
        if (signal == SIGABRT) hint = ": aborted, e.g. an uncaught exception or a failed assert";
        return "crashed (" + name + ", signal " + std::to_string(signal) + ")" + hint;
    }
    if (exitStatus != 0) {
        if (output.find("bad_alloc") != std::string::npos)
            return "ran out of memory (allocation failed under the memory limit)";
        return "exited with status " + std::to_string(exitStatus);
    }
    return "finished";
}

ProcessOutcome runProcess(const std::vector<std::string>& argv, const ProcessLimits& limits) {
    ProcessOutcome outcome;
    int pipeFds[2];
    if (::pipe2(pipeFds, O_CLOEXEC) != 0) return outcome;
    const auto start = std::chrono::steady_clock::now();
    const pid_t pid = ::fork();
    if (pid < 0) {
        ::close(pipeFds[0]);
        ::close(pipeFds[1]);
        return outcome;
    }
    if (pid == 0) {
        // Child: its own process group (so a timeout kills everything it started), its limits,
        // output into the pipe.
        ::setpgid(0, 0);
        if (limits.memoryBytes > 0) {
            const rlimit memory{static_cast<rlim_t>(limits.memoryBytes),
                                static_cast<rlim_t>(limits.memoryBytes)};
            ::setrlimit(RLIMIT_AS, &memory);
        }
        const rlimit noCore{0, 0};
        ::setrlimit(RLIMIT_CORE, &noCore);
        ::dup2(pipeFds[1], STDOUT_FILENO);
        ::dup2(pipeFds[1], STDERR_FILENO);
        std::vector<char*> args;
        for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
        args.push_back(nullptr);
        ::execv(args[0], args.data());
        ::_exit(127);
    }
    ::setpgid(pid, pid);
    ::close(pipeFds[1]);
    outcome.started = true;

    auto elapsed = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    bool open = true;
    char buffer[4096];
    while (open) {
        const double left = limits.wallSeconds - elapsed();
        if (left <= 0) {
            outcome.timedOut = true;
            ::kill(-pid, SIGKILL);
            break;
        }
        pollfd fd{pipeFds[0], POLLIN, 0};
        const int ready = ::poll(&fd, 1, static_cast<int>(std::min(left, 0.25) * 1000) + 1);
        if (ready > 0) {
            const ssize_t n = ::read(pipeFds[0], buffer, sizeof buffer);
            if (n <= 0) {
                open = false;
            } else {
                outcome.output.append(buffer, static_cast<size_t>(n));
                if (outcome.output.size() > (64u << 10))
                    outcome.output.erase(0, outcome.output.size() - (64u << 10));
            }
        }
    }
    // The pipe closed (or we killed it): wait for the exit, still within the limit.
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
    ::close(pipeFds[0]);
    outcome.seconds = elapsed();
    if (WIFEXITED(status)) outcome.exitStatus = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) outcome.signal = WTERMSIG(status);
    if (outcome.timedOut) outcome.signal = 0;
    return outcome;
}

} // namespace pathlab::grader
