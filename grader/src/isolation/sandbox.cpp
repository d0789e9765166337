#include "isolation/sandbox.h"

#include "isolation/user_namespaces.h"

#include "process/child_process.h"

#include <algorithm>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace pathlab::grader {

namespace {

namespace fs = std::filesystem;

/// Where the sandbox's first process, the grader's own (sandbox_init.cpp), is inside.
constexpr const char* InitInside = "/pathlab/init";

/// A host file copied into the sandbox: open here, handed to bubblewrap as a descriptor.
struct CopiedFile {
    int fd = -1;
    std::string inside;
    bool executable = false;
};

/// The host files of `run` (and the init) opened, a folder's regular files one by one; on a file
/// that cannot be opened, `problem` names it and what is open so far is returned to be closed.
std::vector<CopiedFile> openCopiedFiles(const SandboxRun& run, std::string& problem) {
    std::vector<std::pair<std::string, std::string>> files = {{PATHLAB_SANDBOX_INIT, InitInside}};
    for (const auto& [host, inside] : run.files) {
        std::error_code error;
        if (!fs::is_directory(host, error)) {
            files.push_back({host, inside});
            continue;
        }
        for (const auto& entry : fs::recursive_directory_iterator(host, error))
            if (fs::is_regular_file(entry.symlink_status(error)))
                files.push_back({entry.path().string(),
                                 inside + "/" + entry.path().lexically_relative(host).string()});
    }
    std::vector<CopiedFile> opened;
    for (const auto& [host, inside] : files) {
        const int fd = ::open(host.c_str(), O_RDONLY | O_CLOEXEC);
        struct stat info {};
        if (fd < 0 || ::fstat(fd, &info) != 0) {
            problem =
                "cannot read " + host + " to copy it into the sandbox: " + std::strerror(errno);
            if (fd >= 0) ::close(fd);
            return opened;
        }
        opened.push_back({fd, inside, (info.st_mode & S_IXUSR) != 0});
    }
    return opened;
}

std::vector<std::string> bubblewrapArguments(const SandboxRun& run,
                                             const std::vector<CopiedFile>& copied) {
    std::vector<std::string> a = {
        "/usr/bin/bwrap",
        // New namespaces for everything (no network: only a loopback that is down), dying with
        // the grader, in a session of its own (no terminal to inject keys into). Its first
        // process is ours (--as-pid-1): nothing of bubblewrap's is inside for a submission to
        // read or take over.
        "--unshare-all", "--unshare-user", "--disable-userns", "--die-with-parent", "--new-session",
        "--as-pid-1", "--hostname", "pathlab", "--cap-drop", "ALL", "--clearenv", "--setenv",
        "PATH", "/usr/bin:/bin", "--setenv", "HOME", SandboxScratch, "--setenv", "TMPDIR",
        SandboxScratch, "--setenv", "LC_ALL", "C",
        // The system, read-only; of /etc only what finds libraries: the loader's cache and the
        // alternatives' links (no passwd, no keys).
        "--ro-bind", "/usr", "/usr", "--ro-bind-try", "/etc/ld.so.cache", "/etc/ld.so.cache",
        "--ro-bind-try", "/etc/alternatives", "/etc/alternatives", "--proc", "/proc", "--dev",
        "/dev", "--size", std::to_string(run.scratchBytes), "--tmpfs", SandboxScratch, "--chdir",
        SandboxScratch,
        // Of the host's kernel, nothing a render needs and a submission could print: its boot
        // options, its build, its symbols (unreadable, where the kernel lets a sandbox open it).
        "--ro-bind-try", "/dev/null", "/proc/cmdline", "--ro-bind-try", "/dev/null",
        "/proc/version", "--ro-bind-try", "/dev/null", "/proc/kallsyms"};
    // Merged-/usr systems link /bin, /lib... into /usr; older ones have real folders.
    for (const char* top : {"/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32"}) {
        std::error_code error;
        if (fs::is_symlink(top, error))
            a.insert(a.end(), {"--symlink", fs::read_symlink(top).string(), top});
        else if (fs::is_directory(top, error))
            a.insert(a.end(), {"--ro-bind", top, top});
    }
    // Copied, not bound: a bind mount's source path is shown by /proc/self/mountinfo.
    for (size_t i = 0; i < copied.size(); ++i)
        a.insert(a.end(), {"--perms", copied[i].executable ? "0555" : "0444", "--file",
                           std::to_string(FirstPassedFd + static_cast<int>(i)), copied[i].inside});
    for (const auto& [host, inside] : run.bound) a.insert(a.end(), {"--ro-bind", host, inside});
    for (const auto& [name, value] : run.environment) a.insert(a.end(), {"--setenv", name, value});
    // Last, once every file is in place: the sandbox's root and /dev are memory without a size
    // limit, so they become read-only; only the scratch folder stays writable.
    a.insert(a.end(), {"--remount-ro", "/dev", "--remount-ro", "/"});
    a.push_back(InitInside);
    a.insert(a.end(), run.collect.begin(), run.collect.end());
    a.push_back("--");
    a.insert(a.end(), run.command.begin(), run.command.end());
    return a;
}

/// Reads the init's first line, "ended exit N" (or signal N, stopped N), into `process`.
std::string parseEnding(const std::string& line, ProcessOutcome& process) {
    const auto words = [&](const char* prefix, int& number) {
        const size_t length = std::strlen(prefix);
        if (line.compare(0, length, prefix) != 0) return false;
        try {
            number = std::stoi(line.substr(length));
        } catch (const std::exception&) {
            return false;
        }
        return true;
    };
    int number = 0;
    if (words("ended exit ", number)) {
        process.exitStatus = number;
    } else if (words("ended signal ", number)) {
        process.exitStatus = -1;
        process.signal = number;
    } else if (words("ended stopped ", number)) {
        process.exitStatus = -1;
        process.stoppedBy = number;
    } else if (words("ended unstarted ", number)) {
        process.exitStatus = 127;
    } else {
        return "the sandbox's report is malformed";
    }
    return "";
}

/// Splits the init's stream: its ending line, then "NAME SIZE\n" and SIZE bytes, repeated.
std::string parseCollected(const std::string& stream, const std::vector<std::string>& expected,
                           ProcessOutcome& process, std::map<std::string, std::string>& files) {
    size_t at = stream.find('\n');
    if (at == std::string::npos) return "the sandbox said nothing of how the command ended";
    if (std::string problem = parseEnding(stream.substr(0, at), process); !problem.empty())
        return problem;
    ++at;
    while (at < stream.size()) {
        const size_t newline = stream.find('\n', at);
        if (newline == std::string::npos) return "a file's header is cut short";
        const std::string header = stream.substr(at, newline - at);
        const size_t space = header.rfind(' ');
        if (space == std::string::npos) return "a file's header is malformed";
        const std::string name = header.substr(0, space);
        size_t size = 0;
        try {
            size = std::stoull(header.substr(space + 1));
        } catch (const std::exception&) {
            return "a file's size is malformed";
        }
        if (std::find(expected.begin(), expected.end(), name) == expected.end())
            return "an unexpected file came back";
        at = newline + 1;
        if (stream.size() - at < size)
            return name + " is shorter than announced (changed while read?)";
        files[name] = stream.substr(at, size);
        at += size;
    }
    return "";
}

} // namespace

SandboxOutcome runInSandbox(const SandboxRun& run, const ProcessLimits& limits,
                            const SandboxPolicy& policy) {
    SandboxOutcome outcome;
    const std::vector<CopiedFile> copied = openCopiedFiles(run, outcome.problem);
    const auto closeCopied = [&] {
        for (const CopiedFile& file : copied) ::close(file.fd);
    };
    if (!outcome.problem.empty()) {
        closeCopied();
        return outcome;
    }
    ProcessOptions options;
    options.cpus = policy.cpus;
    options.user = policy.user;
    options.collectBytes = static_cast<size_t>(run.scratchBytes) + 4096;
    for (const CopiedFile& file : copied) options.passedFds.push_back(file.fd);
    // Nothing of the grader's environment, its input or its other open files reaches bubblewrap.
    options.isolated = true;
    // The process limit counts every process of the user: it is ours only when the command
    // runs as a user of its own (a grader running as root); otherwise it would count the
    // instructor's desktop too. Lab code is kept from starting processes by the submission
    // viewer's seccomp filter in any case.
    ProcessLimits ownLimits = limits;
    if (policy.user < 0) ownLimits.processes = 0;
    outcome.process = runProcess(bubblewrapArguments(run, copied), ownLimits, options);
    closeCopied();
    ProcessOutcome& p = outcome.process;
    const bool initRan = p.started && !p.timedOut && p.signal == 0 && p.exitStatus == 0;
    if (p.collectOverflow)
        outcome.problem = "it left more in its scratch folder than allowed";
    else if (initRan)
        outcome.problem = parseCollected(p.collected, run.collect, p, outcome.files);
    p.collected.clear();
    return outcome;
}

std::string sandboxUnavailableReason() {
    if (::access("/usr/bin/bwrap", X_OK) != 0)
        return "bubblewrap (/usr/bin/bwrap) is not installed: apt-get install bubblewrap";
    SandboxRun probe;
    probe.command = {"/bin/true"};
    const SandboxOutcome o = runInSandbox(probe, {20, 0}, {{}, sandboxUserForThisProcess()});
    if (o.process.succeeded() && o.problem.empty()) return "";
    const std::string said = o.problem.empty() ? o.process.outputTail(2) : o.problem;
    const std::string cannot =
        "bubblewrap cannot make a sandbox here (" + o.process.describe() + "): " + said + ". ";
    // Run as root, the sandbox runs as an unused user id (sandboxUserForThisProcess), which must
    // read the kit's files copied into it: not so for a kit in /root, mode 700.
    if (::geteuid() == 0 && said.find("Permission denied") != std::string::npos)
        return cannot + "Run as root, the grader sandboxes as an unused user id, which must read "
                        "the kit: make its folder and those above it readable by all users";
    if (const std::string remedy = userNamespaceRemedy(); !remedy.empty()) return cannot + remedy;
    // Inside a chroot or a container, bwrap cannot make its mounts ("Failed to make / slave").
    return cannot + "If this is a chroot or a container, grade on the host, or give the "
                    "container its own mount namespace (e.g. docker run --privileged)";
}

int sandboxUserForThisProcess() {
    if (::geteuid() != 0) return -1;
    // A block of ids no account uses, one per grading process, so that each submission's
    // process limit counts its own processes only.
    return 3'500'000 + static_cast<int>(::getpid() % 500'000);
}

void killProcessesOf(int user) {
    if (user < 0) return;
    // The one fork outside process/child_process.h: this child runs no program, only kill(2) as
    // that user, which takes a process of that user. The helper starts programs; it offers no way
    // to run our own code in a child, where only async-signal-safe calls may be made.
    const pid_t pid = ::fork();
    if (pid == 0) {
        // As that user, "every process I may signal" is exactly that user's processes.
        if (::setgid(static_cast<gid_t>(user)) == 0 && ::setuid(static_cast<uid_t>(user)) == 0)
            ::kill(-1, SIGKILL);
        ::_exit(0);
    }
    if (pid > 0) ::waitpid(pid, nullptr, 0);
}

} // namespace pathlab::grader
