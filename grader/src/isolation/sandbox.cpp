#include "isolation/sandbox.h"

#include "isolation/user_namespaces.h"

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <sys/wait.h>
#include <unistd.h>

namespace pathlab::grader {

namespace {

namespace fs = std::filesystem;

const std::string collectScript = std::string(PATHLAB_GRADER_DIR) + "/sandbox/collect.sh";

std::vector<std::string> bubblewrapArguments(const SandboxRun& run) {
    std::vector<std::string> a = {
        "/usr/bin/bwrap",
        // New namespaces for everything (no network: only a loopback that is down), dying
        // with the grader, in a session of its own (no terminal to inject keys into).
        "--unshare-all", "--unshare-user", "--disable-userns", "--die-with-parent", "--new-session",
        "--cap-drop", "ALL", "--clearenv", "--setenv", "PATH", "/usr/bin:/bin", "--setenv", "HOME",
        SandboxScratch, "--setenv", "TMPDIR", SandboxScratch, "--setenv", "LC_ALL", "C",
        // The system, read-only; of /etc only what finds libraries: the loader's cache and the
        // alternatives' links (no passwd, no keys).
        "--ro-bind", "/usr", "/usr", "--ro-bind-try", "/etc/ld.so.cache", "/etc/ld.so.cache",
        "--ro-bind-try", "/etc/alternatives", "/etc/alternatives", "--proc", "/proc", "--dev",
        "/dev", "--size", std::to_string(run.scratchBytes), "--tmpfs", SandboxScratch, "--chdir",
        SandboxScratch, "--ro-bind", collectScript, "/pathlab/collect.sh"};
    // Merged-/usr systems link /bin, /lib... into /usr; older ones have real folders.
    for (const char* top : {"/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32"}) {
        std::error_code error;
        if (fs::is_symlink(top, error))
            a.insert(a.end(), {"--symlink", fs::read_symlink(top).string(), top});
        else if (fs::is_directory(top, error))
            a.insert(a.end(), {"--ro-bind", top, top});
    }
    for (const auto& [host, inside] : run.files) a.insert(a.end(), {"--ro-bind", host, inside});
    for (const auto& [name, value] : run.environment) a.insert(a.end(), {"--setenv", name, value});
    // Last, once every mount point exists: the sandbox's root and /dev are memory without a
    // size limit, so they become read-only; only the scratch folder stays writable.
    a.insert(a.end(), {"--remount-ro", "/dev", "--remount-ro", "/"});
    a.insert(a.end(), {"/bin/sh", "/pathlab/collect.sh"});
    a.insert(a.end(), run.collect.begin(), run.collect.end());
    a.push_back("--");
    a.insert(a.end(), run.command.begin(), run.command.end());
    return a;
}

/// Splits collect.sh's stream: "NAME SIZE\n" then SIZE bytes, repeated.
std::string parseCollected(const std::string& stream, const std::vector<std::string>& expected,
                           std::map<std::string, std::string>& files) {
    size_t at = 0;
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
    ProcessOptions options;
    options.cpus = policy.cpus;
    options.user = policy.user;
    options.collectBytes = static_cast<size_t>(run.scratchBytes) + 4096;
    // The process limit counts every process of the user: it is ours only when the command
    // runs as a user of its own (a grader running as root); otherwise it would count the
    // instructor's desktop too. Lab code is kept from starting processes by the submission
    // viewer's seccomp filter in any case.
    ProcessLimits ownLimits = limits;
    if (policy.user < 0) ownLimits.processes = 0;
    outcome.process = runProcess(bubblewrapArguments(run), ownLimits, options);
    // The shell reports a command that a signal ended as 128 + the signal.
    ProcessOutcome& p = outcome.process;
    if (p.exitStatus > 128 && p.exitStatus < 128 + 65) {
        p.signal = p.exitStatus - 128;
        p.exitStatus = -1;
    }
    if (p.collectOverflow)
        outcome.problem = "it left more in its scratch folder than allowed";
    else
        outcome.problem = parseCollected(p.collected, run.collect, outcome.files);
    p.collected.clear();
    return outcome;
}

std::string sandboxUnavailableReason() {
    if (::access("/usr/bin/bwrap", X_OK) != 0)
        return "bubblewrap (/usr/bin/bwrap) is not installed: apt-get install bubblewrap";
    SandboxRun probe;
    probe.command = {"/bin/true"};
    const SandboxOutcome o = runInSandbox(probe, {20, 0}, {{}, sandboxUserForThisProcess()});
    if (o.process.succeeded()) return "";
    const std::string said = o.process.outputTail(2);
    const std::string cannot =
        "bubblewrap cannot make a sandbox here (" + o.process.describe() + "): " + said + ". ";
    // Run as root, the sandbox runs as an unused user id (sandboxUserForThisProcess), which must
    // read the kit's files bound into it: not so for a kit in /root, mode 700.
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
