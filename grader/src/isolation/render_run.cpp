#include "isolation/render_run.h"

#include "common/scene_files.h"

#include "pathlab/images/image_io.h"
#include "pathlab/support/input_error.h"
#include "pathlab/support/whole_file.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <thread>

namespace pathlab::grader {

namespace {

namespace fs = std::filesystem;

/// Where the viewer writes the path inspector's JSON, in the scratch folder (or the sandbox's).
constexpr const char* ReplayFile = "replay.json";

/// A render may print this much; what follows is not read (ProcessOutcome::outputNote).
constexpr size_t RenderOutputBytes = 4u << 20;

/// The start of the line the viewer's watchdog prints when a lab finishes no sample
/// (pathlab/render/render_watchdog.h).
constexpr const char* WatchdogWords = "render watchdog: ";

std::vector<std::string> viewerArguments(const RenderRequest& r, const std::string& scene,
                                         const std::string& image, const std::string& stats,
                                         const std::string& replay, const RenderLimits& limits) {
    // A submission's viewer runs its loaded library as its student table: never --solution.
    RenderIdentity identity = r.identity;
    if (r.runner->sandboxed()) identity.implementation = Implementation::Student;
    std::vector<std::string> argv = {"-c", scene};
    for (std::string& argument : renderIdentityArguments(identity)) argv.push_back(argument);
    argv.insert(argv.end(), {"--spp", std::to_string(r.spp), "--seeds", std::to_string(r.seeds),
                             "-o", image, "--stats", stats});
    // A lab that finishes no sample is stopped by the viewer's watchdog, which says so; one
    // that keeps finishing samples is stopped only by its CPU time (renderLab).
    char stall[32];
    std::snprintf(stall, sizeof stall, "%g", limits.stallSeconds);
    argv.insert(argv.end(), {"--watchdog", stall});
    if (r.threads > 0) argv.insert(argv.end(), {"--threads", std::to_string(r.threads)});
    if (r.reverseTiles) argv.push_back("--reverse-tiles");
    if (r.inspectSamples > 0)
        argv.insert(argv.end(), {"--inspect", std::to_string(r.inspectX),
                                 std::to_string(r.inspectY), "--inspect-samples",
                                 std::to_string(r.inspectSamples), "--inspect-out", replay});
    return argv;
}

/// The files the viewer writes for seed `seed` of a request: named as viewer --seeds names them.
std::pair<std::string, std::string> outputNames(const RenderRequest& r, uint64_t seed) {
    // .pfm: written without OpenImageIO, whose loading would cost each render more than a
    // small render takes (image_io.h).
    if (r.seeds == 1) return {"render.pfm", "render.json"};
    return {"render-" + std::to_string(seed) + ".pfm", "render-" + std::to_string(seed) + ".json"};
}

/// The render's threads: its --threads, or the cores it may run on.
unsigned renderThreads(const RenderRequest& r) {
    if (r.threads > 0) return static_cast<unsigned>(r.threads);
    const std::vector<int>& cpus = r.runner->sandboxed() ? r.runner->sandbox.cpus : r.runner->cpus;
    if (!cpus.empty()) return static_cast<unsigned>(cpus.size());
    return std::max(1u, std::thread::hardware_concurrency());
}

/// The process limits of a render: its CPU time over its threads, the last-resort wall clock,
/// memory, and how much of its output is read.
ProcessLimits processLimits(const RenderRequest& r, const RenderLimits& limits) {
    ProcessLimits p;
    p.wallSeconds = limits.wallSeconds;
    p.memoryBytes = limits.memoryBytes;
    p.cpuSeconds = limits.cpuSecondsPerThread * renderThreads(r);
    p.outputReadBytes = RenderOutputBytes;
    return p;
}

/// Runs the submission viewer in the sandbox and puts the images and stats it leaves into the
/// request's scratch folder on the host (those it finished, also when it failed). Returns a
/// problem in words, or "".
std::string renderSandboxed(const RenderRequest& r, const RenderLimits& limits,
                            ProcessOutcome& process) {
    const SandboxedScene scene = sandboxedScene(r.scene);
    SandboxRun run;
    run.command = {"/pathlab/viewer"};
    const auto arguments =
        viewerArguments(r, scene.ecs, "render.pfm", "render.json", ReplayFile, limits);
    run.command.insert(run.command.end(), arguments.begin(), arguments.end());
    // No image-file plug-in: the viewer writes the .pfm it is asked for without one.
    run.files = {{r.runner->viewer, "/pathlab/viewer"},
                 {r.runner->libraryFor(r.identity.lab), "/pathlab/labs.so"}};
    run.files.insert(run.files.end(), scene.files.begin(), scene.files.end());
    run.environment = {{"PATHLAB_LABS_LIBRARY", "/pathlab/labs.so"}};
    for (int k = 0; k < r.seeds; ++k) {
        const auto [image, stats] = outputNames(r, r.identity.seed + static_cast<uint64_t>(k));
        run.collect.insert(run.collect.end(), {image, stats});
    }
    if (r.inspectSamples > 0) run.collect.push_back(ReplayFile);
    run.scratchBytes = 64LL << 20;
    ProcessLimits sandboxLimits = processLimits(r, limits);
    sandboxLimits.fileBytes = 64LL << 20;
    // Threads count as processes: 64 for the viewer's own (the window-less render thread, TBB's
    // helpers) beside one per render thread, so a node of 64 cores or more can render on all.
    sandboxLimits.processes = 64 + static_cast<int>(renderThreads(r));
    SandboxOutcome outcome = runInSandbox(run, sandboxLimits, r.runner->sandbox);
    process = outcome.process;
    if (!outcome.problem.empty()) return outcome.problem;
    for (const auto& [name, bytes] : outcome.files)
        std::ofstream(r.scratch + "/" + name, std::ios::binary) << bytes;
    if (!process.succeeded()) return "";
    for (const std::string& name : run.collect)
        if (!outcome.files.count(name)) return "it wrote no " + name;
    return "";
}

/// Reads one seed's image and stats from the scratch folder into `rendered`; returns why it
/// cannot, in words, with `kind` in a few, or "".
std::string readRendered(const RenderRequest& r, uint64_t seed, RenderedImage& rendered,
                         std::string& kind) {
    const auto [imageName, statsName] = outputNames(r, seed);
    try {
        rendered.statsFile = r.scratch + "/" + statsName;
        std::ifstream in(rendered.statsFile);
        const nlohmann::json s = nlohmann::json::parse(in);
        if (const int nonfinite = s.at("nonfinite_pixels"); nonfinite > 0) {
            kind = NonfiniteRadianceFailure;
            return "returned NaN or infinite radiance in " + std::to_string(nonfinite) +
                   " pixels (a division by a zero probability?)";
        }
        rendered.rays = {s.at("rays").at("intersect"), s.at("rays").at("occluded")};
        const Image read = readImage(r.scratch + "/" + imageName);
        // The lab runs in the process that writes this file: what it holds is checked, not trusted.
        if (read.width != r.identity.width || read.height != r.identity.height)
            throw std::runtime_error("the image is " + std::to_string(read.width) + "x" +
                                     std::to_string(read.height) + ", not the size asked for");
        rendered.rgb = read.rgb;
    } catch (const std::exception& e) {
        kind = "unreadable output";
        return std::string("its output could not be read: ") + e.what();
    }
    return "";
}

/// The seeds' images of a request that are in the scratch folder.
int seedsFinished(const RenderRequest& r) {
    int finished = 0;
    for (int k = 0; k < r.seeds; ++k)
        if (fs::exists(r.scratch + "/" +
                       outputNames(r, r.identity.seed + static_cast<uint64_t>(k)).first))
            ++finished;
    return finished;
}

/// Why a render's process failed, in words for the student and in a few (its kind), with the
/// lines it printed last.
void describeFailure(const RenderRequest& r, const RenderLimits& limits, RenderResult& result) {
    const ProcessOutcome& p = result.process;
    std::string printed = p.outputTail(8);
    const size_t watchdog = printed.find(WatchdogWords);
    char words[200];
    if (p.exitStatus == 1 && watchdog != std::string::npos) {
        // The watchdog's own line names the viewer's option: the grader's words say it instead.
        printed.erase(watchdog);
        std::snprintf(words, sizeof words,
                      "finished no sample for %g s: an endless loop, or recursion that never "
                      "ends?",
                      limits.stallSeconds);
        result.failure = words;
        result.failureKind = "endless loop";
    } else if (p.usedUpCpuTime() && r.seeds == 0) {
        // A tool run (runLabTool), which renders no seed.
        std::snprintf(words, sizeof words,
                      "used up its CPU time (%.0f s): too slow for the limit (%g s per thread)",
                      p.cpuSeconds, limits.cpuSecondsPerThread);
        result.failure = words;
        result.failureKind = "too slow";
    } else if (p.usedUpCpuTime()) {
        std::snprintf(words, sizeof words,
                      "finished %d of %d seeds in %.0f s of CPU time: too slow for the limit "
                      "(%g s per render thread)",
                      seedsFinished(r), r.seeds, p.cpuSeconds, limits.cpuSecondsPerThread);
        result.failure = words;
        result.failureKind = "too slow";
    } else {
        result.failure = p.describe();
        result.failureKind = p.timedOut         ? "wall-clock limit"
                             : p.stoppedBy != 0 ? "stopped itself"
                             : p.signal != 0    ? "crashed"
                             : result.failure.find("memory") != std::string::npos
                                 ? "out of memory"
                                 : "exited with an error";
    }
    while (!printed.empty() && (printed.back() == '\n' || printed.back() == ' '))
        printed.pop_back();
    if (!printed.empty()) result.failure += "; it printed: " + printed;
    if (!result.outputNote.empty()) result.failure += " (" + result.outputNote + ")";
}

} // namespace

SandboxedScene sandboxedScene(const std::string& ecsPath) {
    const fs::path folder = fs::absolute(ecsPath).parent_path();
    std::vector<std::pair<std::string, fs::path>> relative;
    size_t depth = 0; // how far above the .ecs's folder its files reach ("../meshes/x.obj")
    for (const std::string& file : sceneFiles(ecsPath)) {
        const fs::path rel = fs::absolute(file).lexically_normal().lexically_relative(folder);
        size_t up = 0;
        for (const fs::path& part : rel) up += part == ".." ? 1 : 0;
        depth = std::max(depth, up);
        relative.push_back({file, rel});
    }
    fs::path root = "/scene";
    for (size_t i = 0; i < depth; ++i) root /= "in";
    SandboxedScene scene;
    scene.ecs = (root / fs::absolute(ecsPath).lexically_normal().filename()).string();
    for (const auto& [host, rel] : relative)
        scene.files.push_back({host, (root / rel).lexically_normal().string()});
    return scene;
}

RenderResult renderLab(const RenderRequest& r, const RenderLimits& limits) {
    RenderResult result;
    for (int k = 0; k < r.seeds; ++k) {
        const auto [image, stats] = outputNames(r, r.identity.seed + static_cast<uint64_t>(k));
        fs::remove(r.scratch + "/" + image);
        fs::remove(r.scratch + "/" + stats);
    }
    fs::remove(r.scratch + "/" + ReplayFile);
    std::string problem;
    if (r.runner->sandboxed()) {
        problem = renderSandboxed(r, limits, result.process);
    } else {
        std::vector<std::string> argv = {r.runner->viewer};
        const auto arguments =
            viewerArguments(r, r.scene, r.scratch + "/render.pfm", r.scratch + "/render.json",
                            r.scratch + "/" + ReplayFile, limits);
        argv.insert(argv.end(), arguments.begin(), arguments.end());
        ProcessOptions options;
        options.cpus = r.runner->cpus;
        result.process = runProcess(argv, processLimits(r, limits), options);
    }
    result.outputNote = result.process.outputNote();
    if (!result.process.succeeded()) {
        describeFailure(r, limits, result);
        return result;
    }
    if (!problem.empty()) {
        result.failureKind = "unreadable output";
        result.failure = "its output could not be read: " + problem;
        return result;
    }
    for (int k = 0; k < r.seeds; ++k) {
        result.failure = readRendered(r, r.identity.seed + static_cast<uint64_t>(k),
                                      result.images.emplace_back(), result.failureKind);
        if (!result.failure.empty()) return result;
    }
    if (r.inspectSamples > 0) {
        try {
            result.replayJson = readFile(r.scratch + "/" + ReplayFile);
        } catch (const InputError&) {
            result.failureKind = "unreadable output";
            result.failure = std::string("it wrote no ") + ReplayFile;
            return result;
        }
    }
    result.width = r.identity.width;
    result.height = r.identity.height;
    result.ok = true;
    return result;
}

std::vector<double> regionMeans(const std::vector<float>& image, int width, int height, int tiles) {
    const int regions = 1 + tiles * tiles;
    std::vector<double> sums(3 * regions, 0.0);
    std::vector<double> counts(regions, 0.0);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const int tile = 1 + (y * tiles / height) * tiles + (x * tiles / width);
            for (int region : {0, tile}) {
                counts[region] += 1;
                for (int c = 0; c < 3; ++c)
                    sums[3 * region + c] += image[3 * (static_cast<size_t>(y) * width + x) + c];
            }
        }
    }
    for (int region = 0; region < regions; ++region)
        for (int c = 0; c < 3; ++c) sums[3 * region + c] /= counts[region];
    return sums;
}

LabToolRun runLabTool(const LabToolRequest& request, const RenderLimits& limits) {
    const LabRunner& runner = *request.runner;
    // A request of no seed, for the process limits and the failure's words.
    RenderRequest r;
    r.runner = &runner;
    r.identity.lab = request.lab;
    r.scratch = request.scratch;
    r.threads = 1;
    r.seeds = 0;
    char stall[32];
    std::snprintf(stall, sizeof stall, "%g", limits.stallSeconds);
    std::vector<std::string> arguments = {
        "--lab", std::string(labName(request.lab)), "--watchdog", stall, "--threads", "1"};
    if (!runner.sandboxed() && runner.implementation == Implementation::Solution)
        arguments.push_back("--solution");
    LabToolRun run;
    RenderResult result;
    const std::string& name = request.collect;
    if (!name.empty()) fs::remove(request.scratch + "/" + name);
    if (runner.sandboxed()) {
        SandboxRun sandboxed;
        sandboxed.command = {"/pathlab/viewer"};
        sandboxed.files = {{runner.viewer, "/pathlab/viewer"},
                           {runner.libraryFor(request.lab), "/pathlab/labs.so"}};
        if (!request.scene.empty()) {
            const SandboxedScene scene = sandboxedScene(request.scene);
            sandboxed.command.insert(sandboxed.command.end(), {"-c", scene.ecs});
            sandboxed.files.insert(sandboxed.files.end(), scene.files.begin(), scene.files.end());
        }
        sandboxed.command.insert(sandboxed.command.end(), request.arguments.begin(),
                                 request.arguments.end());
        sandboxed.command.insert(sandboxed.command.end(), arguments.begin(), arguments.end());
        sandboxed.environment = {{"PATHLAB_LABS_LIBRARY", "/pathlab/labs.so"}};
        if (!name.empty()) sandboxed.collect = {name};
        sandboxed.scratchBytes = 64LL << 20;
        ProcessLimits sandboxLimits = processLimits(r, limits);
        sandboxLimits.fileBytes = 64LL << 20;
        sandboxLimits.processes = 64 + 1;
        SandboxOutcome outcome = runInSandbox(sandboxed, sandboxLimits, runner.sandbox);
        result.process = outcome.process;
        if (!name.empty() && outcome.files.count(name)) run.bytes = outcome.files[name];
        if (!outcome.problem.empty() && request.succeeded(result.process)) {
            run.failure = "its output could not be read: " + outcome.problem;
            run.failureKind = "unreadable output";
            return run;
        }
    } else {
        std::vector<std::string> argv = {runner.viewer};
        if (!request.scene.empty()) argv.insert(argv.end(), {"-c", request.scene});
        for (const std::string& argument : request.arguments)
            argv.push_back(argument == name ? request.scratch + "/" + name : argument);
        argv.insert(argv.end(), arguments.begin(), arguments.end());
        ProcessOptions options;
        options.cpus = runner.cpus;
        result.process = runProcess(argv, processLimits(r, limits), options);
        if (!name.empty() && request.succeeded(result.process)) {
            try {
                run.bytes = readFile(request.scratch + "/" + name);
            } catch (const InputError&) {
            }
        }
    }
    run.output = result.process.output;
    result.outputNote = result.process.outputNote();
    if (!request.succeeded(result.process)) {
        describeFailure(r, limits, result);
        run.failure = result.failure;
        run.failureKind = result.failureKind;
        return run;
    }
    if (!name.empty() && run.bytes.empty()) {
        run.failure = "it wrote no " + name;
        run.failureKind = "unreadable output";
        return run;
    }
    run.ok = true;
    return run;
}

LabToolRun dumpLobe(const LabRunner& runner, Lab lab, uint64_t seed, const std::string& scratch,
                    const RenderLimits& limits) {
    LabToolRequest request;
    request.runner = &runner;
    request.lab = lab;
    request.scratch = scratch;
    request.collect = "lobe.bin";
    request.arguments = {"--lobe-dump", request.collect, "--seed", std::to_string(seed)};
    return runLabTool(request, limits);
}

RenderIdentity requestedIdentity(const LabRunner& runner, Lab lab, const LabParameters& parameters,
                                 uint64_t seed, int width, int height) {
    return {lab, runner.implementation, parameters, seed, width, height};
}

} // namespace pathlab::grader
