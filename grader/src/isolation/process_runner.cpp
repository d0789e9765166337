// POSIX: Linux and macOS (the grader is not built with MSVC). Pinning to cores is Linux only.
#include "isolation/process_runner.h"

#include "pathlab/support/printable_text.h"

#include "process/child_process.h"

#include <csignal>
#include <cstdio>
#include <cstring>
#include <sys/wait.h>

namespace pathlab::grader {

bool ProcessOutcome::usedUpCpuTime() const {
    // The kernel ends a process at its CPU limit with SIGKILL (soft and hard limit alike) or
    // SIGXCPU; its CPU time then stands at the limit, give or take a tick.
    return cpuLimit > 0 && (signal == SIGKILL || signal == SIGXCPU) &&
           cpuSeconds >= 0.97 * cpuLimit;
}

std::string ProcessOutcome::describe() const {
    if (!started) return "could not be started";
    char figures[160];
    if (timedOut) {
        std::snprintf(figures, sizeof figures,
                      "did not finish within %.0f s of wall-clock time, the last-resort limit",
                      wallLimit);
        return figures;
    }
    if (stoppedBy != 0)
        return "stopped its own process (" + std::string(strsignal(stoppedBy)) + ", signal " +
               std::to_string(stoppedBy) +
               "), which would only have waited for the time limit: a lab must not stop or "
               "signal the process it runs in";
    if (usedUpCpuTime()) {
        std::snprintf(figures, sizeof figures, "used up its CPU time limit of %.0f s", cpuLimit);
        return figures;
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
        if (signal == SIGSYS) hint = ": a system call the sandbox forbids";
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

std::string ProcessOutcome::outputNote() const {
    if (!outputCutOff) return "";
    return "it printed more than " + std::to_string(outputReadBytes >> 20) +
           " MiB: what followed was not read (printing slows a render down; leave it out of "
           "pathTrace)";
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
        // What a lab printed goes into logs, terminals and pages: no control byte of its own
        // (an escape sequence that rewrites the log's lines as a terminal shows them, a bell).
        if (!line.empty()) kept.insert(kept.begin(), printableText(line));
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
    setup.passedFds = options.passedFds;
    setup.isolated = options.isolated;
    // Each sandbox leaves an orphan to reap: reaped here, whatever this process's ancestors do.
    setup.reapOrphans = true;
    RunLimits runLimits{limits.wallSeconds, 64u << 10, options.collectBytes};
    if (limits.outputReadBytes > 0) runLimits.outputReadBytes = limits.outputReadBytes;
    const ChildRun run = runChild(argv, setup, runLimits);

    ProcessOutcome outcome;
    outcome.wallLimit = limits.wallSeconds;
    outcome.cpuLimit = limits.cpuSeconds;
    outcome.outputReadBytes = limits.outputReadBytes;
    if (!run.started) return outcome;
    static_cast<ChildRun&>(outcome) = run;
    if (WIFEXITED(run.waitStatus)) outcome.exitStatus = WEXITSTATUS(run.waitStatus);
    if (WIFSIGNALED(run.waitStatus) && !run.timedOut) outcome.signal = WTERMSIG(run.waitStatus);
    return outcome;
}

} // namespace pathlab::grader
