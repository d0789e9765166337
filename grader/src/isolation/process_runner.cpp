// POSIX: Linux and macOS (the grader is not built with MSVC). Pinning to cores is Linux only.
#include "isolation/process_runner.h"

#include "process/child_process.h"

#include <csignal>
#include <cstdio>
#include <cstring>
#include <sys/wait.h>

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
        // Long enough for a failed check, which names the lab's line, what to fix and the
        // framework's check; short enough that a flood of output stays readable.
        if (line.size() > 600) line = line.substr(0, 600) + "...";
        if (!line.empty()) kept.insert(kept.begin(), line);
        if (start == std::string::npos) break;
        end = start;
    }
    std::string tail;
    for (const std::string& line : kept) tail += (tail.empty() ? "" : "\n") + line;
    return tail;
}

ProcessOutcome runProcess(const std::vector<std::string>& argv, const ProcessLimits& limits,
                          const ProcessOptions& options) {
    ChildSetup setup;
    // Its own process group, so that a timeout kills everything it started.
    setup.ownProcessGroup = true;
#ifndef PATHLAB_SANITIZED
    setup.limits.addressSpaceBytes = limits.memoryBytes;
#else
    // AddressSanitizer reserves terabytes of address space at start-up: a limit on it would
    // stop every sanitized program the grader runs (CI's sanitizer builds).
    (void)limits.memoryBytes;
#endif
    if (limits.cpuSeconds > 0)
        setup.limits.cpuSeconds = static_cast<long long>(limits.cpuSeconds + 1);
    setup.limits.fileBytes = limits.fileBytes;
    setup.limits.processes = limits.processes;
    setup.limits.noCoreFiles = true;
    setup.cpus = options.cpus;
    setup.user = options.user;
    setup.collectPipe = options.collectBytes > 0;
    // Each sandbox leaves an orphan to reap: reaped here, whatever this process's ancestors do.
    setup.reapOrphans = true;
    const ChildRun run =
        runChild(argv, setup, {limits.wallSeconds, 64u << 10, options.collectBytes});

    ProcessOutcome outcome;
    outcome.wallLimit = limits.wallSeconds;
    if (!run.started) return outcome;
    outcome.started = true;
    outcome.timedOut = run.timedOut;
    outcome.seconds = run.seconds;
    outcome.output = run.output;
    outcome.collected = run.collected;
    outcome.collectOverflow = run.collectOverflow;
    if (WIFEXITED(run.waitStatus)) outcome.exitStatus = WEXITSTATUS(run.waitStatus);
    if (WIFSIGNALED(run.waitStatus) && !run.timedOut) outcome.signal = WTERMSIG(run.waitStatus);
    return outcome;
}

} // namespace pathlab::grader
