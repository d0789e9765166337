#include "pathlab/render/lab_crash_line.h"

#include "pathlab/support/this_process.h"

#include <atomic>
#include <cstring>
#include <string>

#if defined(__unix__) || defined(__APPLE__)
#include <csignal>
#include <unistd.h>
#include <vector>
#define PATHLAB_CRASH_LINE 1
#endif

namespace pathlab {

#if PATHLAB_CRASH_LINE

namespace {

/// Each lab's line for each implementation, written before any crash: a signal handler may only
/// write what is ready.
constexpr std::size_t MaxLine = 600;
char lines[2 * LabCount][MaxLine];
std::size_t lineLengths[2 * LabCount];
std::atomic<int> runningLine{-1};

struct sigaction replacedSegv, replacedBus;
std::atomic<int> installed{0};

int lineIndex(const WatchedLab& lab) {
    return static_cast<int>(labIndex(lab.lab)) * 2 +
           (lab.implementation == Implementation::Student ? 0 : 1);
}

void writeLines() {
    const bool terminal = standardErrorIsTerminal();
    for (Lab lab : AllLabs)
        for (Implementation impl : {Implementation::Student, Implementation::Solution}) {
            const std::string file =
                (impl == Implementation::Student ? "labs/" : "solutions/") + labFileName(lab);
            const std::string line =
                std::string(terminal ? "\n" : "") + "lab " + std::to_string(labNumber(lab)) + " (" +
                std::string(labName(lab)) + ", " + file +
                ") crashed: a recursion that never ends (a path with no depth limit or Russian "
                "roulette overflows the stack), or a bad pointer? Look in " +
                file + " for the test that ends a path, and for an index out of range.\n";
            const int i = lineIndex({lab, impl});
            const std::size_t length = std::min(line.size(), MaxLine);
            std::memcpy(lines[i], line.data(), length);
            lineLengths[i] = length;
        }
}

/// Says which lab crashed, puts back the handler it replaced and returns: the faulting access
/// runs again and meets that handler, or the default, which ends the process by the signal. A
/// signal some process sent (raise, kill) is no fault to name: it is sent again, to be handled
/// as it would have been without this handler.
void onCrash(int signal, siginfo_t* info, void*) {
    ::sigaction(signal, signal == SIGSEGV ? &replacedSegv : &replacedBus, nullptr);
    if (info && info->si_code <= 0) {
        ::raise(signal); // pending until this handler returns
        return;
    }
    const int i = runningLine.load();
    if (i >= 0) {
        ssize_t ignored = ::write(STDERR_FILENO, lines[i], lineLengths[i]);
        (void)ignored;
    }
}

/// A thread's alternate signal stack, given back before the thread's memory is.
struct AlternateStack {
    std::vector<char> memory = std::vector<char>(64 * 1024);
    AlternateStack() {
        stack_t stack{};
        stack.ss_sp = memory.data();
        stack.ss_size = memory.size();
        ::sigaltstack(&stack, nullptr);
    }
    ~AlternateStack() {
        stack_t off{};
        off.ss_flags = SS_DISABLE;
        ::sigaltstack(&off, nullptr);
    }
};

} // namespace

LabCrashLine::LabCrashLine(const WatchedLab& lab) {
    if (installed.fetch_add(1) == 0) {
        writeLines();
        struct sigaction action {};
        action.sa_sigaction = onCrash;
        action.sa_flags = SA_ONSTACK | SA_SIGINFO;
        sigemptyset(&action.sa_mask);
        ::sigaction(SIGSEGV, &action, &replacedSegv);
        ::sigaction(SIGBUS, &action, &replacedBus);
    }
    running(lab);
    prepareCrashStack();
}

LabCrashLine::~LabCrashLine() {
    if (installed.fetch_sub(1) != 1) return;
    ::sigaction(SIGSEGV, &replacedSegv, nullptr);
    ::sigaction(SIGBUS, &replacedBus, nullptr);
    runningLine = -1;
}

void LabCrashLine::running(const WatchedLab& lab) { runningLine = lineIndex(lab); }

void LabCrashLine::prepareCrashStack() {
    thread_local AlternateStack stack;
    (void)stack;
}

#else

LabCrashLine::LabCrashLine(const WatchedLab&) {}
LabCrashLine::~LabCrashLine() {}
void LabCrashLine::running(const WatchedLab&) {}
void LabCrashLine::prepareCrashStack() {}

#endif

} // namespace pathlab
