// The grader's sandbox itself (isolation/sandbox.h), commands run in it as a submission's would
// be: nothing of the host reaches them (environment, paths, descriptors), no process inside can
// reach another (ptrace) or leave its cores, one that stops itself is said to have, and what is
// copied in is copied, links not followed. Linux with bubblewrap only; where bubblewrap cannot
// make a sandbox (a chroot, a container), the test says so and checks nothing.
#include "catch.h"

#if PATHLAB_SANDBOX

#include "isolation/sandbox.h"
#include "sandbox_here.h"

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace pathlab::grader;

namespace fs = std::filesystem;

namespace {

SandboxOutcome inSandbox(const std::string& script,
                         const std::vector<std::pair<std::string, std::string>>& files = {}) {
    SandboxRun run;
    run.command = {"/bin/sh", "-c", script};
    run.files = files;
    run.collect = {"out.txt"};
    return runInSandbox(run, {30, 0}, {{}, sandboxUserForThisProcess()});
}

/// A folder of this test's own, removed with the object.
struct Folder {
    std::string path;
    Folder() {
        char pattern[] = "/tmp/pathlab-sandbox-test-XXXXXX";
        path = ::mkdtemp(pattern);
        fs::permissions(path, fs::perms::owner_all | fs::perms::others_read |
                                  fs::perms::others_exec | fs::perms::group_read |
                                  fs::perms::group_exec);
    }
    ~Folder() { fs::remove_all(path); }
};

} // namespace

TEST_CASE("nothing of the grader's environment, paths or descriptors reaches the sandbox",
          "[grader][sandbox]") {
    if (!sandboxHere()) return;
    Folder host;
    std::ofstream(host.path + "/scene.ecs") << "-i scene.obj\n";
    ::setenv("PATHLAB_SANDBOX_TEST_SECRET", "hunter2", 1);
    const SandboxOutcome o =
        inSandbox("cat /proc/self/environ /proc/1/cmdline /proc/self/mountinfo /proc/self/cgroup "
                  "> out.txt; ls -l /proc/self/fd/ >> out.txt; cat /proc/1/environ 2>> out.txt; "
                  "cat /scene/scene.ecs >> out.txt",
                  {{host.path + "/scene.ecs", "/scene/scene.ecs"}});
    ::unsetenv("PATHLAB_SANDBOX_TEST_SECRET");
    REQUIRE(o.process.succeeded());
    REQUIRE(o.files.count("out.txt"));
    const std::string seen = o.files.at("out.txt");
    CHECK(seen.find("hunter2") == std::string::npos);
    CHECK(seen.find(host.path) == std::string::npos);          // the copied file's host path
    CHECK(seen.find(PATHLAB_GRADER_DIR) == std::string::npos); // the kit's
    CHECK(seen.find("-i scene.obj") != std::string::npos);     // copied, at its neutral path
    // The first process is the grader's and unreadable; its command line names nothing of the host.
    CHECK(seen.find("/proc/1/environ: Permission denied") != std::string::npos);
    CHECK(seen.find("/pathlab/init") != std::string::npos);
}

TEST_CASE("no process of the sandbox may trace another or widen its cores", "[grader][sandbox]") {
    if (!sandboxHere()) return;
    // Python's ctypes calls ptrace(PTRACE_ATTACH, 1) directly, as a lab's code would.
    const SandboxOutcome o = inSandbox(
        "python3 -c 'import ctypes, os\n"
        "libc = ctypes.CDLL(None, use_errno=True)\n"
        "print(\"ptrace\", libc.ptrace(16, 1, 0, 0), os.strerror(ctypes.get_errno()))\n"
        "try:\n    os.sched_setaffinity(0, range(os.cpu_count())); print(\"affinity WIDENED\")\n"
        "except OSError as e:\n    print(\"affinity\", e.strerror)' > out.txt");
    REQUIRE(o.files.count("out.txt"));
    const std::string said = o.files.at("out.txt");
    CHECK(said.find("ptrace -1 Operation not permitted") != std::string::npos);
    CHECK(said.find("affinity Operation not permitted") != std::string::npos);
}

TEST_CASE("a command that stops itself is said to have, not left to the time limit",
          "[grader][sandbox]") {
    if (!sandboxHere()) return;
    const SandboxOutcome o = inSandbox("kill -STOP $$");
    CHECK(o.process.stoppedBy == SIGSTOP);
    CHECK_FALSE(o.process.timedOut);
    CHECK(o.process.seconds < 10);
    CHECK(o.process.describe().find("stopped its own process") == 0);
}

TEST_CASE("a folder is copied in file by file, its links not followed", "[grader][sandbox]") {
    if (!sandboxHere()) return;
    Folder host, secret;
    std::ofstream(secret.path + "/answer.txt") << "42\n";
    fs::create_directories(host.path + "/include/pathlab");
    std::ofstream(host.path + "/include/pathlab/lab.h") << "// lab\n";
    fs::create_symlink(secret.path + "/answer.txt", host.path + "/include/pathlab/answer.txt");
    const SandboxOutcome o = inSandbox("find /kit -type f > out.txt; cat /kit/pathlab/* >> out.txt",
                                       {{host.path + "/include", "/kit"}});
    REQUIRE(o.files.count("out.txt"));
    const std::string seen = o.files.at("out.txt");
    CHECK(seen.find("/kit/pathlab/lab.h") != std::string::npos);
    CHECK(seen.find("42") == std::string::npos);
}

#endif
