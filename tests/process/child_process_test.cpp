// Starting programs (process/): what the grader, the benchmark and the tests rely on. POSIX only,
// as the library's child processes are.
#include "catch.h"
#include "test_support.h"

#include "process/child_process.h"
#include "process/shell_command.h"

#include <chrono>
#include <csignal>
#include <cstdio>
#include <fcntl.h>
#include <fstream>
#include <iterator>
#include <sstream>
#include <sys/wait.h>
#if defined(__linux__)
#include <sys/prctl.h>
#endif
#include <thread>
#include <unistd.h>
#include <vector>

using namespace pathlab;

namespace {

ChildRun shell(const std::string& script, const ChildSetup& setup = {},
               const RunLimits& limits = {}) {
    return runChild({"/bin/sh", "-c", script}, setup, limits);
}

} // namespace

TEST_CASE("a child's output, both streams together, and its exit status", "[process]") {
    const ChildRun run = shell("echo out; echo err >&2; exit 3");
    CHECK(run.started);
    CHECK_FALSE(run.timedOut);
    CHECK(run.exitCode == 3);
    CHECK(run.output == "out\nerr\n");
}

TEST_CASE("a child ended by a signal: 128 + the signal, as a shell says", "[process]") {
    const ChildRun run = shell("kill -TERM $$");
    CHECK(run.exitCode == 128 + 15);
    CHECK(WIFSIGNALED(run.waitStatus));
}

TEST_CASE("a program that cannot be run exits with 127", "[process]") {
    const ChildRun run = runChild({"/nonexistent/program"});
    CHECK(run.started);
    CHECK(run.exitCode == 127);
}

TEST_CASE("the time limit kills a child and everything in its process group", "[process]") {
    const std::string folder = test::temporaryFolder("process-group");
    ChildSetup setup;
    setup.ownProcessGroup = true;
    // The grandchild would write its file after the limit, had it not been killed with its parent.
    const ChildRun run = shell("(sleep 1; touch " + folder + "/left) & sleep 30", setup, {0.3});
    CHECK(run.timedOut);
    CHECK(run.seconds < 5);
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));
    CHECK_FALSE(std::ifstream(folder + "/left"));
}

TEST_CASE("the last bytes of the output, the first of descriptor 3", "[process]") {
    ChildSetup setup;
    setup.collectPipe = true;
    const ChildRun kept = shell("printf 0123456789; printf abc >&3", setup, {10, 4, 3});
    CHECK(kept.output == "6789");
    CHECK(kept.collected == "abc");
    CHECK_FALSE(kept.collectOverflow);
    const ChildRun over = shell("printf abcd >&3", setup, {10, 4, 3});
    CHECK(over.collected.empty());
    CHECK(over.collectOverflow);
}

TEST_CASE("resource limits hold in the child", "[process]") {
    ChildSetup setup;
    setup.limits.fileBytes = 4096;
    setup.limits.noCoreFiles = true;
    CHECK(shell("ulimit -f; ulimit -c", setup).output == "8\n0\n"); // ulimit counts 512-byte blocks
}

TEST_CASE("output to a file; children started together, reaped as each ends", "[process]") {
    const std::string folder = test::temporaryFolder("process-file");
    ChildSetup setup;
    setup.outputFile = folder + "/log";
    std::vector<ChildProcess> children;
    children.emplace_back(std::vector<std::string>{"/bin/sh", "-c", "sleep 30"}, ChildSetup{});
    children.emplace_back(std::vector<std::string>{"/bin/sh", "-c", "echo logged; exit 4"}, setup);
    while (!children[1].poll()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    CHECK(children[1].exitCode() == 4);
    CHECK(children[1].outputPipe() < 0);
    std::stringstream log;
    log << std::ifstream(folder + "/log").rdbuf();
    CHECK(log.str() == "logged\n");
    CHECK_FALSE(children[0].poll());
    CHECK(children[0].exitCode() == -1);
    children[0].kill();
    children[0].wait();
    CHECK(children[0].exitCode() == 128 + 9);
}

#if defined(__linux__)
TEST_CASE("reapOrphans: what the program leaves is reaped before it counts as ended; its exit "
          "status and signal are kept",
          "[process]") {
    // While this runs, orphans come to this process, as they come to a container's first
    // process that never reaps them: a descendant the child leaves behind stays here a zombie.
    REQUIRE(::prctl(PR_SET_CHILD_SUBREAPER, 1) == 0);
    const auto leaveOrphan = [](bool reapOrphans) {
        ChildSetup setup;
        setup.reapOrphans = reapOrphans;
        const ChildRun run = shell("sleep 0.2 >/dev/null 2>&1 & echo $!; exit 5", setup);
        CHECK(run.exitCode == 5);
        return std::stoi(run.output);
    };
    const auto state = [](int pid) {
        std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
        std::string text((std::istreambuf_iterator<char>(stat)), {});
        const size_t name = text.rfind(')');
        return name == std::string::npos ? '-' : text.at(name + 2); // '-': no such process
    };

    const int reaped = leaveOrphan(true);
    CHECK(state(reaped) == '-');

    const int left = leaveOrphan(false);
    for (int i = 0; i < 400 && state(left) != 'Z'; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    CHECK(state(left) == 'Z');
    ::waitpid(left, nullptr, 0);
    ::prctl(PR_SET_CHILD_SUBREAPER, 0);

    ChildSetup setup;
    setup.reapOrphans = true;
    CHECK(shell("kill -XCPU $$", setup).exitCode == 128 + SIGXCPU);
    CHECK(runChild({"/nonexistent/program"}, setup, {}).exitCode == 127);
}
#endif

TEST_CASE("passed descriptors arrive in order at 10, 11, ... whatever numbers they had here; an "
          "isolated child gets nothing else: no environment, /dev/null for input, no other "
          "descriptor",
          "[process]") {
    // Files opened here at low numbers, some the very numbers the child's copies are to take.
    std::vector<int> opened;
    std::vector<std::string> paths;
    for (int i = 0; i < 4; ++i) {
        paths.push_back("/tmp/pathlab-passed-" + std::to_string(::getpid()) + "-" +
                        std::to_string(i));
        std::ofstream(paths.back()) << "file " << i << "\n";
    }
    // File i at descriptor 10 + i here: passed in the reverse order, each must move onto the
    // number another one holds.
    for (int i = 3; i >= 0; --i) {
        const int fd = ::open(paths[static_cast<size_t>(i)].c_str(), O_RDONLY);
        ::dup2(fd, 10 + i);
        ::close(fd);
        opened.push_back(10 + i);
    }
    // A descriptor left open without close-on-exec, which an isolated child must not inherit.
    const int stray = ::open("/dev/zero", O_RDONLY);
    ::setenv("PATHLAB_PASSED_TEST", "inherited", 1);
    ChildSetup setup;
    setup.passedFds = opened;
    setup.isolated = true;
    const ChildRun run = runChild({"/bin/sh", "-c",
                                   "cat /proc/self/fd/10 /proc/self/fd/11 /proc/self/fd/12 "
                                   "/proc/self/fd/13; echo \"env:${PATHLAB_PASSED_TEST:-none}\"; "
                                   "cat; ls /proc/self/fd | tr '\\n' ' '"},
                                  setup);
    ::unsetenv("PATHLAB_PASSED_TEST");
    for (int fd : opened) ::close(fd);
    ::close(stray);
    for (const std::string& path : paths) std::remove(path.c_str());
    INFO(run.output);
    CHECK(run.exitCode == 0);
    CHECK(run.output.find("file 3\nfile 2\nfile 1\nfile 0\nenv:none\n") == 0);
    // Its own 0, 1, 2, the four passed, and the one ls holds to read the folder.
    const std::string descriptors = run.output.substr(run.output.rfind('\n') + 1);
    CHECK(descriptors == "0 1 10 11 12 13 2 3 ");
}

TEST_CASE("output past outputReadBytes is not read: the pipe closes and the child's writes fail",
          "[process]") {
    RunLimits limits;
    limits.outputReadBytes = 1 << 20;
    // 100 MB of output, which read to the end would take a while; yes dies of SIGPIPE at the cut.
    const auto start = std::chrono::steady_clock::now();
    // With a reaper between (it never execs): it must hold no copy of our end of the pipe, or the
    // child would block on a full pipe instead of failing.
    ChildSetup setup;
#if defined(__linux__)
    setup.reapOrphans = true;
#endif
    const ChildRun run =
        runChild({"/bin/sh", "-c", "head -c 100000000 /dev/zero | tr '\\0' x"}, setup, limits);
    CHECK(run.outputCutOff);
    CHECK(run.output.size() <= limits.outputReadBytes + (64u << 10));
    CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(30));
    const ChildRun small = runChild({"/bin/sh", "-c", "echo short"}, {}, limits);
    CHECK_FALSE(small.outputCutOff);
    CHECK(small.output == "short\n");
}

TEST_CASE("a child's CPU time is the kernel's count, its descendants' included", "[process]") {
    // A fixed amount of work (a shell counting), in one background process, then in two: the
    // CPU time doubles, whatever the machine's load makes of the wall time.
    const std::string count = "(i=0; while [ $i -lt 200000 ]; do i=$((i+1)); done) & ";
    const ChildRun one = runChild({"/bin/sh", "-c", count + "wait"});
    const ChildRun two = runChild({"/bin/sh", "-c", count + count + "wait"});
    CHECK(one.exitCode == 0);
    CHECK(one.cpuSeconds > 0.02);
    INFO("one: " << one.cpuSeconds << " s, two: " << two.cpuSeconds << " s");
    CHECK(two.cpuSeconds / one.cpuSeconds > 1.5);
    CHECK(two.cpuSeconds / one.cpuSeconds < 2.7);
    CHECK(shell("true").cpuSeconds < 0.5);
}

TEST_CASE("a program found in PATH", "[process]") {
    CHECK(findProgram("sh").find("/sh") != std::string::npos);
    CHECK(findProgram("/bin/sh") == "/bin/sh");
    CHECK(findProgram("pathlab-no-such-program").empty());
}

TEST_CASE("a shell command's status and output", "[process]") {
    const ShellCommandResult result = runShellCommand("echo 'a b'; echo c >&2; exit 2");
    CHECK(result.exitStatus == 2);
    CHECK(result.output == "a b\nc\n");
}
