// POSIX: Linux and macOS. Pinning to cores and dying with the parent are Linux only.
#include "process/child_process.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <grp.h>
#include <poll.h>
#include <sstream>
#include <utility>
#if defined(__linux__)
#include <sched.h>
#include <sys/prctl.h>
#endif
#include <sys/resource.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

namespace pathlab {

namespace {

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

void closeIfOpen(int& fd) {
    if (fd >= 0) ::close(fd);
    fd = -1;
}

/// Everything the child needs between fork and exec, made before the fork: the parent may have
/// other threads, one of which may hold the allocator's lock when it forks, so the child only
/// makes system calls (no allocation, no locks) until exec replaces it.
struct ChildPlan {
    std::vector<char*> argv;
    std::vector<std::pair<int, rlimit>> limits;
#if defined(__linux__)
    bool pinned = false;
    cpu_set_t cpus;
#endif
    /// What was asked for: its flags, user and passed descriptors are read in the child.
    ChildSetup setup;
    int outputFd = -1;  ///< becomes its stdout and stderr (-1: ours)
    int collectFd = -1; ///< becomes its descriptor 3 (-1: none)
    int nullInput = -1; ///< /dev/null, its input when isolated
    /// Our read ends of its pipes: closed in the child at once, so that no process of its (the
    /// reaper, which never execs) keeps one open, and its writes fail when we close ours.
    int ourEnds[2] = {-1, -1};
};

ChildPlan planFor(const std::vector<std::string>& argv, const ChildSetup& setup) {
    ChildPlan plan;
    for (const std::string& a : argv) plan.argv.push_back(const_cast<char*>(a.c_str()));
    plan.argv.push_back(nullptr);
    const auto limit = [&](int resource, long long value) {
        const auto v = static_cast<rlim_t>(value);
        plan.limits.push_back({resource, rlimit{v, v}});
    };
    const ResourceLimits& l = setup.limits;
    if (l.addressSpaceBytes > 0) limit(RLIMIT_AS, l.addressSpaceBytes);
    if (l.cpuSeconds > 0) limit(RLIMIT_CPU, l.cpuSeconds);
    if (l.fileBytes > 0) limit(RLIMIT_FSIZE, l.fileBytes);
    if (l.processes > 0) limit(RLIMIT_NPROC, l.processes);
    if (l.noCoreFiles) limit(RLIMIT_CORE, 0);
#if defined(__linux__)
    CPU_ZERO(&plan.cpus);
    for (int cpu : setup.cpus) CPU_SET(cpu, &plan.cpus);
    plan.pinned = !setup.cpus.empty();
#endif
    plan.setup = setup;
    return plan;
}

#if defined(__linux__)
/// In the child (async-signal-safe calls only): forks the process that goes on to run the
/// program, and returns in it. This process stays, as the reaper of the program's descendants:
/// it waits until every one has ended, then ends as the program ended (exit status or signal).
void interposeReaper() {
    if (::prctl(PR_SET_CHILD_SUBREAPER, 1) != 0) return; // no reaper: the program runs here
    const pid_t program = ::fork();
    if (program < 0) ::_exit(127);
    if (program == 0) {
        ::prctl(PR_SET_PDEATHSIG, SIGKILL); // it goes with its reaper
        return;
    }
    int programStatus = 0, status = 0;
    for (pid_t ended; (ended = ::waitpid(-1, &status, 0)) != -1 || errno == EINTR;)
        if (ended == program) programStatus = status;
    if (WIFSIGNALED(programStatus)) {
        const int signal = WTERMSIG(programStatus);
        const rlimit noCore{0, 0};
        ::setrlimit(RLIMIT_CORE, &noCore);
        ::signal(signal, SIG_DFL);
        sigset_t only;
        sigemptyset(&only);
        sigaddset(&only, signal);
        ::sigprocmask(SIG_UNBLOCK, &only, nullptr);
        ::kill(::getpid(), signal);
    }
    ::_exit(WIFEXITED(programStatus) ? WEXITSTATUS(programStatus) : 127);
}
#endif

/// In the child: closes descriptors `from` to `to` - 1 (to -1: every one from `from` on).
void closeDescriptorsFrom(int from, int to) {
    const long open = ::sysconf(_SC_OPEN_MAX);
    const int end = to >= 0 ? to : static_cast<int>(open > 0 ? std::min(open, 1L << 20) : 1024);
#if defined(__linux__) && defined(SYS_close_range)
    if (from < end && ::syscall(SYS_close_range, from, end - 1, 0) == 0) return;
#endif
    for (int fd = from; fd < end; ++fd) ::close(fd);
}

/// In the child, between fork and exec: only async-signal-safe calls.
[[noreturn]] void becomeChild(const ChildPlan& plan) {
    for (int end : plan.ourEnds)
        if (end >= 0) ::close(end);
#if defined(__linux__)
    if (plan.setup.dieWithParent) ::prctl(PR_SET_PDEATHSIG, SIGKILL);
#endif
    if (plan.setup.ownProcessGroup) ::setpgid(0, 0);
#if defined(__linux__)
    // Before the limits and the user: the reaper stays as we are, and its fork is not counted
    // against the program's process limit.
    if (plan.setup.reapOrphans) interposeReaper();
#endif
    for (const auto& [resource, limit] : plan.limits) ::setrlimit(resource, &limit);
#if defined(__linux__)
    if (plan.pinned) ::sched_setaffinity(0, sizeof plan.cpus, &plan.cpus);
#endif
    if (plan.setup.user >= 0) {
        const auto id = static_cast<uid_t>(plan.setup.user);
        if (::setgroups(0, nullptr) != 0 || ::setgid(id) != 0 || ::setuid(id) != 0) ::_exit(126);
    }
    // The passed descriptors, first copied above the numbers they are to take (closed at exec),
    // so that none is overwritten by another's move before it moved itself.
    const int passed = static_cast<int>(plan.setup.passedFds.size());
    int moved[256];
    if (passed > 256) ::_exit(127);
    for (int i = 0; i < passed; ++i)
        if ((moved[i] = ::fcntl(plan.setup.passedFds[i], F_DUPFD_CLOEXEC, FirstPassedFd + passed)) <
            0)
            ::_exit(127);
    if (plan.outputFd >= 0) {
        ::dup2(plan.outputFd, STDOUT_FILENO);
        ::dup2(plan.outputFd, STDERR_FILENO);
    }
    if (plan.collectFd >= 0) ::dup2(plan.collectFd, 3); // dup2 clears close-on-exec on the copy
    if (plan.setup.isolated && (plan.nullInput < 0 || ::dup2(plan.nullInput, STDIN_FILENO) < 0))
        ::_exit(127);
    // Only now: a descriptor number they take may have been one of those above.
    for (int i = 0; i < passed; ++i)
        if (::dup2(moved[i], FirstPassedFd + i) < 0) ::_exit(127);
    if (plan.setup.isolated) {
        closeDescriptorsFrom(plan.collectFd >= 0 ? 4 : 3, FirstPassedFd);
        closeDescriptorsFrom(FirstPassedFd + passed, -1);
        char* noEnvironment[] = {nullptr};
        ::execve(plan.argv[0], plan.argv.data(), noEnvironment);
        ::_exit(127);
    }
    ::execv(plan.argv[0], plan.argv.data());
    ::_exit(127);
}

/// Appends what is ready on `fd` to `text`, keeping at most `keep` bytes (the last ones when
/// `keepTail`, else the first, flagging `overflow`). Returns how many bytes were read: 0 at end
/// of file.
size_t drain(int fd, std::string& text, size_t keep, bool keepTail, bool& overflow) {
    char buffer[65536];
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n <= 0) return 0;
    if (keepTail) {
        text.append(buffer, static_cast<size_t>(n));
        if (text.size() > keep) text.erase(0, text.size() - keep);
    } else if (text.size() + static_cast<size_t>(n) > keep) {
        overflow = true;
    } else {
        text.append(buffer, static_cast<size_t>(n));
    }
    return static_cast<size_t>(n);
}

} // namespace

ChildProcess::ChildProcess(const std::vector<std::string>& argv, const ChildSetup& setup) {
    ChildPlan plan = planFor(argv, setup);
    // Ours are the read ends; the child's ends (or the file it writes to) close here once it
    // has them.
    int outputPipe[2] = {-1, -1}, collectPipe[2] = {-1, -1};
    bool ready = true;
    if (!setup.outputFile.empty())
        outputPipe[1] =
            ::open(setup.outputFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    else
        ready = openPipe(outputPipe);
    if (ready && setup.collectPipe) ready = openPipe(collectPipe);
    int nullInput = setup.isolated ? ::open("/dev/null", O_RDONLY | O_CLOEXEC) : -1;
    plan.nullInput = nullInput;
    plan.outputFd = outputPipe[1];
    plan.collectFd = collectPipe[1];
    plan.ourEnds[0] = outputPipe[0];
    plan.ourEnds[1] = collectPipe[0];
    const pid_t pid = ready ? ::fork() : -1;
    if (pid == 0) becomeChild(plan);
    closeIfOpen(outputPipe[1]);
    closeIfOpen(collectPipe[1]);
    closeIfOpen(nullInput);
    if (pid < 0) {
        closeIfOpen(outputPipe[0]);
        closeIfOpen(collectPipe[0]);
        return;
    }
    // Here too, so that a kill() right after this finds the group.
    if (setup.ownProcessGroup) ::setpgid(pid, pid);
    pid_ = pid;
    output_ = outputPipe[0];
    collect_ = collectPipe[0];
    ownGroup_ = setup.ownProcessGroup;
}

ChildProcess::ChildProcess(ChildProcess&& other) noexcept { swap(other); }

ChildProcess& ChildProcess::operator=(ChildProcess&& other) noexcept {
    ChildProcess moved(std::move(other));
    swap(moved);
    return *this;
}

ChildProcess::~ChildProcess() {
    closeIfOpen(output_);
    closeIfOpen(collect_);
}

void ChildProcess::swap(ChildProcess& other) noexcept {
    std::swap(pid_, other.pid_);
    std::swap(output_, other.output_);
    std::swap(collect_, other.collect_);
    std::swap(ownGroup_, other.ownGroup_);
    std::swap(reaped_, other.reaped_);
    std::swap(status_, other.status_);
    std::swap(cpuSeconds_, other.cpuSeconds_);
}

namespace {

double seconds(const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * t.tv_usec; }

} // namespace

bool ChildProcess::poll() {
    if (!started()) return true;
    rusage usage{};
    if (!reaped_ && ::wait4(pid_, &status_, WNOHANG, &usage) == pid_) {
        reaped_ = true;
        cpuSeconds_ = seconds(usage.ru_utime) + seconds(usage.ru_stime);
    }
    return reaped_;
}

void ChildProcess::wait() {
    if (reaped_ || !started()) return;
    rusage usage{};
    while (::wait4(pid_, &status_, 0, &usage) < 0 && errno == EINTR) {
    }
    reaped_ = true;
    cpuSeconds_ = seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

int ChildProcess::exitCode() const {
    if (!reaped_) return -1;
    if (WIFEXITED(status_)) return WEXITSTATUS(status_);
    return WIFSIGNALED(status_) ? 128 + WTERMSIG(status_) : -1;
}

void ChildProcess::closeOutput() { closeIfOpen(output_); }

void ChildProcess::kill() {
    if (!started()) return;
    if (ownGroup_)
        ::kill(-pid_, SIGKILL);
    else if (!reaped_) // once reaped, its id may be another process's
        ::kill(pid_, SIGKILL);
}

ChildRun runChild(const std::vector<std::string>& argv, const ChildSetup& setup,
                  const RunLimits& limits) {
    ChildRun run;
    const auto start = std::chrono::steady_clock::now();
    ChildProcess child(argv, setup);
    if (!child.started()) return run;
    run.started = true;

    auto elapsed = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    // Read both pipes until both close or time runs out.
    bool outputOpen = child.outputPipe() >= 0, collectOpen = child.collectPipe() >= 0;
    bool ignored = false;
    size_t outputRead = 0;
    while (outputOpen || collectOpen) {
        const double left = limits.wallSeconds - elapsed();
        if (left <= 0) {
            run.timedOut = true;
            child.kill();
            break;
        }
        pollfd fds[2] = {{outputOpen ? child.outputPipe() : -1, POLLIN, 0},
                         {collectOpen ? child.collectPipe() : -1, POLLIN, 0}};
        if (::poll(fds, 2, static_cast<int>(std::min(left, 0.25) * 1000) + 1) <= 0) continue;
        if (fds[0].revents != 0) {
            const size_t read =
                drain(child.outputPipe(), run.output, limits.outputBytes, true, ignored);
            outputOpen = read > 0;
            outputRead += read;
            if (outputOpen && outputRead > limits.outputReadBytes) {
                run.outputCutOff = true;
                outputOpen = false;
                child.closeOutput();
            }
        }
        if (fds[1].revents != 0)
            collectOpen = drain(child.collectPipe(), run.collected, limits.collectBytes, false,
                                run.collectOverflow) > 0;
    }
    // The pipes closed (or it was killed): wait for the end, still within the limit.
    while (!child.poll()) {
        if (elapsed() > limits.wallSeconds) {
            run.timedOut = true;
            child.kill();
            child.wait();
            break;
        }
        ::usleep(2000);
    }
    child.kill(); // anything it left behind in its own group
    run.seconds = elapsed();
    run.waitStatus = child.waitStatus();
    run.exitCode = child.exitCode();
    run.cpuSeconds = child.cpuSeconds();
    return run;
}

std::string findProgram(const std::string& program) {
    namespace fs = std::filesystem;
    const auto executable = [](const fs::path& p) {
        return fs::is_regular_file(p) && ::access(p.c_str(), X_OK) == 0;
    };
    if (program.find('/') != std::string::npos) return executable(program) ? program : "";
    const char* path = std::getenv("PATH");
    std::istringstream folders(path ? path : "");
    for (std::string folder; std::getline(folders, folder, ':');) {
        const fs::path candidate = fs::path(folder.empty() ? "." : folder) / program;
        if (executable(candidate)) return candidate.string();
    }
    return "";
}

} // namespace pathlab
