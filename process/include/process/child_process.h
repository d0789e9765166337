#pragma once
/// Starting another program as a child process and seeing it end: PathLab's one way of doing
/// so (the grader's renders, compilers and sandbox, `grader batch`'s workers, the benchmark, the
/// tests). POSIX only (Linux and macOS); Windows has only shell_command.h.

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace pathlab {

/// The descriptor number of the first of ChildSetup::passedFds in the child.
constexpr int FirstPassedFd = 10;

/// Limits the kernel holds a child to (setrlimit, soft and hard alike); 0 leaves one inherited.
struct ResourceLimits {
    long long addressSpaceBytes = 0; ///< RLIMIT_AS
    long long cpuSeconds = 0;        ///< RLIMIT_CPU: SIGXCPU after this much CPU time
    long long fileBytes = 0;         ///< RLIMIT_FSIZE: the largest file it may write
    long long processes = 0;         ///< RLIMIT_NPROC: processes of its user
    bool noCoreFiles = false;        ///< RLIMIT_CORE 0: a crash leaves no core file
};

/// How a child starts. What is not set here it inherits: environment, working folder, stdin.
struct ChildSetup {
    /// A process group of its own, so that ChildProcess::kill ends everything it started.
    bool ownProcessGroup = false;
    bool dieWithParent = false; ///< killed (SIGKILL) if this process dies first; Linux only
    ResourceLimits limits;
    std::vector<int> cpus; ///< run only on these cores (empty: any); Linux only
    int user = -1;         ///< run as this user and group id (needs root; -1: as we are)
    /// Standard output and standard error both go to this file, created or truncated (ours if it
    /// cannot be opened); empty: to a pipe this process reads (ChildProcess::outputPipe).
    std::string outputFile;
    /// A pipe as its file descriptor 3 too, for what it hands back (ChildProcess::collectPipe).
    bool collectPipe = false;
    /// Open files it is given as descriptors FirstPassedFd, FirstPassedFd + 1, ... in this order
    /// (they stay open here; the caller closes them once the child is started).
    std::vector<int> passedFds;
    /// It starts with nothing of this process but what is named here: no environment, /dev/null
    /// as its input, and no open descriptor but its output, descriptor 3 and `passedFds`
    /// (otherwise it inherits this process's environment, input and descriptors not marked
    /// close-on-exec).
    bool isolated = false;
    /// Linux only: the program runs in a child of a process that waits for every descendant the
    /// program leaves, and then ends as the program did. Bubblewrap leaves its sandbox's first
    /// process to whoever reaps orphans; where that is a container's first process that never
    /// reaps, each sandbox would leave a zombie, counted against its user's process limit.
    bool reapOrphans = false;
};

/// A child process: started by the constructor, ended by the program it runs. Moved, not
/// copied; one still running when this object goes is left running.
class ChildProcess {
public:
    ChildProcess() = default;
    /// Starts the program at the path `argv[0]` (findProgram finds one in PATH) with the
    /// arguments `argv[1..]`. If no pipe or process can be had, started() is false; a program
    /// that cannot be run exits with status 127 (126: the user could not be switched).
    ChildProcess(const std::vector<std::string>& argv, const ChildSetup& setup);
    ChildProcess(ChildProcess&& other) noexcept;
    ChildProcess& operator=(ChildProcess&& other) noexcept;
    ChildProcess(const ChildProcess&) = delete;
    ChildProcess& operator=(const ChildProcess&) = delete;
    ~ChildProcess();

    bool started() const { return pid_ > 0; }
    /// The read ends of its output pipe and of its descriptor 3; -1 where it has none.
    int outputPipe() const { return output_; }
    int collectPipe() const { return collect_; }

    /// Whether it has ended (or never started), without waiting; reaps it when it has.
    bool poll();
    /// Waits until it ends (at once if it never started).
    void wait();
    /// How it ended, as waitpid says (once poll() or wait() saw it end).
    int waitStatus() const { return status_; }
    /// Its exit status, or 128 + the signal that ended it as a shell reports it; -1 while it runs.
    int exitCode() const;
    /// The CPU time of it and of the descendants it waited for (once poll() or wait() saw it end).
    double cpuSeconds() const { return cpuSeconds_; }
    /// Stops reading its output: what it writes there from now on fails.
    void closeOutput();
    /// Kills it (SIGKILL). With a process group of its own, the whole group, which may outlive
    /// it: so that also once it has ended.
    void kill();

private:
    void swap(ChildProcess& other) noexcept;

    int pid_ = -1;
    int output_ = -1;
    int collect_ = -1;
    bool ownGroup_ = false;
    bool reaped_ = false;
    int status_ = 0;
    double cpuSeconds_ = 0;
};

/// How long a child may run, and how much of what it writes is kept.
struct RunLimits {
    double wallSeconds = std::numeric_limits<double>::infinity(); ///< killed after this
    size_t outputBytes = std::numeric_limits<size_t>::max();      ///< the last bytes of its output
    size_t collectBytes = std::numeric_limits<size_t>::max(); ///< the first bytes on descriptor 3
    /// Its output is read up to this many bytes; then the pipe is closed, so that what it writes
    /// after fails (EPIPE, or SIGPIPE where it does not ignore that) instead of being read to no
    /// end (ChildRun::outputCutOff).
    size_t outputReadBytes = std::numeric_limits<size_t>::max();
};

/// A child run to its end.
struct ChildRun {
    bool started = false;
    bool timedOut = false;        ///< killed at RunLimits::wallSeconds
    int waitStatus = 0;           ///< as waitpid says
    int exitCode = -1;            ///< as ChildProcess::exitCode
    double seconds = 0;           ///< wall time from its start to its end
    std::string output;           ///< standard output and standard error together
    std::string collected;        ///< what it wrote on descriptor 3
    bool collectOverflow = false; ///< it wrote more there than RunLimits::collectBytes
    bool outputCutOff = false;    ///< it wrote more output than RunLimits::outputReadBytes
    /// CPU time (user and system) of it and of every descendant it waited for, as the kernel
    /// accounts it; a figure the child cannot change.
    double cpuSeconds = 0;
};

/// Starts `argv` as ChildProcess does, reads its pipes until they close and waits for it to end,
/// killing it (and its process group, if it has one) at the time limit.
ChildRun runChild(const std::vector<std::string>& argv, const ChildSetup& setup = {},
                  const RunLimits& limits = {});

/// The full path of `program` found in PATH (or `program` itself if it has a slash and is
/// executable); empty if there is none.
std::string findProgram(const std::string& program);

} // namespace pathlab
