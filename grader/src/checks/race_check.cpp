#include "checks/race_check.h"

#include "isolation/render_run.h"

#include <chrono>
#include <fstream>
#include <sys/utsname.h>
#include <unistd.h>

namespace pathlab::grader {

namespace {

// Small, yet long enough that TBB's second thread joins the render (race_check.h): 16 tiles of
// 16x16, about a second (only the lab is instrumented, so it runs nearly at full speed).
const char* const RaceScene = "cornell_box_VI2_Specular";
constexpr int RaceSize = 64, RaceSpp = 256, RaceThreads = 2;

/// TSan's settings: every report printed and the run not failed for them (this grader reads
/// them); no thread leaks (TBB's workers outlive main) or signal reports, which are not races;
/// symbols found in-process (libbacktrace), never by starting llvm-symbolizer, which the viewer's
/// seccomp filter refuses.
const char* const TsanOptions =
    "exitcode=0 report_thread_leaks=0 report_signal_unsafe=0 "
    "external_symbolizer_path= history_size=4 ignore_noninstrumented_modules=1";

/// Runs the race check's viewer in the sandbox with `arguments`, without an address-space limit
/// (TSan maps terabytes of shadow memory) but with every other.
ProcessOutcome runTsanViewer(const LabBuild& build, const std::vector<std::string>& launcher,
                             const std::vector<std::string>& arguments,
                             const std::vector<std::pair<std::string, std::string>>& files,
                             const SandboxPolicy& policy, double seconds) {
    SandboxRun run;
    run.command = launcher;
    run.command.push_back("/pathlab/viewer");
    run.command.insert(run.command.end(), arguments.begin(), arguments.end());
    run.files = {{build.raceCheckViewer, "/pathlab/viewer"}};
    run.files.insert(run.files.end(), files.begin(), files.end());
    run.environment = {{"TSAN_OPTIONS", TsanOptions}, {"PATHLAB_LABS_LIBRARY", "/pathlab/labs.so"}};
    run.scratchBytes = 64LL << 20;
    ProcessLimits limits;
    limits.wallSeconds = seconds;
    limits.memoryBytes = 0;
    limits.cpuSeconds = seconds * RaceThreads;
    limits.fileBytes = 64LL << 20;
    limits.processes = 64;
    return runInSandbox(run, limits, policy).process;
}

/// `setarch ARCH -R`, which turns address randomisation off for the program it starts.
std::vector<std::string> withoutRandomisation() {
    utsname name{};
    ::uname(&name);
    return {"/usr/bin/setarch", name.machine, "-R"};
}

} // namespace

RaceCheckRuntime raceCheckRuntime(const LabBuild& build, const SandboxPolicy& policy) {
    RaceCheckRuntime runtime;
    runtime.unavailable.clear();
    if (build.raceCheckViewer.empty()) {
        runtime.unavailable = "this build has no ThreadSanitizer viewer (viewer-submission-tsan "
                              "needs GCC with libtsan, in a build not otherwise sanitized)";
        return runtime;
    }
    std::string said;
    for (const bool setarch : {false, true}) {
        if (setarch && ::access("/usr/bin/setarch", X_OK) != 0) break;
        runtime.launcher = setarch ? withoutRandomisation() : std::vector<std::string>{};
        const ProcessOutcome probe =
            runTsanViewer(build, runtime.launcher, {"--help"}, {}, policy, 60);
        if (probe.succeeded() && probe.output.find("ThreadSanitizer") == std::string::npos)
            return runtime;
        said = probe.describe() + ": " + probe.outputTail(2);
    }
    runtime.launcher.clear();
    runtime.unavailable = "ThreadSanitizer's runtime does not start here (" + said + ")";
    return runtime;
}

RaceFinding checkRaces(const RaceCheckRun& run, Lab lab) {
    const auto start = std::chrono::steady_clock::now();
    RaceFinding finding;
    finding.how = "ThreadSanitizer, the VI2 box at " + std::to_string(RaceSize) + "x" +
                  std::to_string(RaceSize) + ", " + std::to_string(RaceSpp) +
                  " samples per pixel, " + std::to_string(RaceThreads) + " threads";
    std::string library;
    const std::string failure = buildRaceCheckLibrary(run.build, run.kit, lab, run.sources,
                                                      run.folder, run.policy, library);
    finding.status = RaceFinding::Status::CouldNotRun;
    if (!failure.empty()) {
        finding.problem = "compiled with ThreadSanitizer: " + failure.substr(0, failure.find('\n'));
        return finding;
    }
    const SandboxedScene scene =
        sandboxedScene(std::string(PATHLAB_MODELS_DIR) + "/" + RaceScene + ".ecs");
    std::vector<std::pair<std::string, std::string>> files = {{library, "/pathlab/labs.so"}};
    files.insert(files.end(), scene.files.begin(), scene.files.end());
    // The lab at the viewer's default parameters: a race does not depend on them.
    const RenderIdentity identity{lab, Implementation::Student, {}, run.seed, RaceSize, RaceSize};
    std::vector<std::string> arguments = {"-c", scene.ecs};
    for (std::string& argument : renderIdentityArguments(identity)) arguments.push_back(argument);
    arguments.insert(arguments.end(), {"--spp", std::to_string(RaceSpp), "--threads",
                                       std::to_string(RaceThreads), "-o", "render.pfm"});
    // Its two threads on the grading's own cores, even one: TSan sees a race by the order of the
    // accesses it records, not by their running at the same instant, and the renderer starts
    // the threads it is asked for on any number of cores. So the check neither waits for nor
    // disturbs the timing core.
    const ProcessOutcome process =
        runTsanViewer(run.build, run.runtime.launcher, arguments, files, run.policy, 60);
    finding.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::string fileName = labFileName(lab);
    finding.races = labRaces(process.output, "/submission/" + fileName, "labs/" + fileName);
    // A race found stands even if the run then failed (a lab that races may well crash).
    if (!finding.races.empty() || process.succeeded()) {
        finding.status = RaceFinding::Status::Ran;
        return finding;
    }
    finding.problem =
        "the render under ThreadSanitizer " + process.describe() + ": " + process.outputTail(2);
    // Its correctness renders loaded the same file built without the sanitizer: a symbol missing
    // only under it comes from code the lab compiles only there (#if __SANITIZE_THREAD__), which
    // would make the check's render not the lab's.
    if (process.output.find("undefined symbol") != std::string::npos)
        finding.status = RaceFinding::Status::LabRefused;
    return finding;
}

} // namespace pathlab::grader
