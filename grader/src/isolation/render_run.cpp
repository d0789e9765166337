#include "isolation/render_run.h"

#include "common/scene_files.h"

#include "pathlab/image_io.h"
#include "pathlab/input_error.h"
#include "pathlab/whole_file.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <thread>

namespace pathlab::grader {

namespace {

namespace fs = std::filesystem;

/// Where the viewer writes the path inspector's JSON, in the scratch folder (or the sandbox's).
constexpr const char* ReplayFile = "replay.json";

std::vector<std::string> viewerArguments(const RenderRequest& r, const std::string& image,
                                         const std::string& stats, const std::string& replay) {
    std::vector<std::string> argv = {"-c",
                                     r.scene,
                                     "--size",
                                     std::to_string(r.width),
                                     std::to_string(r.height),
                                     "--spp",
                                     std::to_string(r.spp),
                                     "--lab",
                                     std::string(labName(r.lab)),
                                     "--max-depth",
                                     std::to_string(r.maxDepth),
                                     "--continue-prob",
                                     std::to_string(r.continueProb),
                                     "--seed",
                                     std::to_string(r.seed),
                                     "--seeds",
                                     std::to_string(r.seeds),
                                     "-o",
                                     image,
                                     "--stats",
                                     stats};
    // The grader's own time limit stops a lab that never returns, and says so (time_limit.h),
    // whatever limit an instructor sets: the viewer's watchdog, which would fire first under a
    // limit longer than its own, is off.
    argv.insert(argv.end(), {"--watchdog", "0"});
    if (!r.runner->sandboxed() && r.runner->implementation == Implementation::Solution)
        argv.push_back("--solution");
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

/// Runs the submission viewer in the sandbox and puts the images and stats it leaves into the
/// request's scratch folder on the host. Returns a problem in words, or "".
std::string renderSandboxed(const RenderRequest& r, const ProcessLimits& limits,
                            ProcessOutcome& process) {
    SandboxRun run;
    run.command = {"/pathlab/viewer"};
    const auto arguments = viewerArguments(r, "render.pfm", "render.json", ReplayFile);
    run.command.insert(run.command.end(), arguments.begin(), arguments.end());
    // No image-file plug-in: the viewer writes the .pfm it is asked for without one.
    run.files = {{r.runner->viewer, "/pathlab/viewer"},
                 {r.runner->libraryFor(r.lab), "/pathlab/labs.so"}};
    for (const std::string& file : sceneFiles(r.scene)) run.files.push_back({file, file});
    run.environment = {{"PATHLAB_LABS_LIBRARY", "/pathlab/labs.so"}};
    for (int k = 0; k < r.seeds; ++k) {
        const auto [image, stats] = outputNames(r, r.seed + static_cast<uint64_t>(k));
        run.collect.insert(run.collect.end(), {image, stats});
    }
    if (r.inspectSamples > 0) run.collect.push_back(ReplayFile);
    run.scratchBytes = 64LL << 20;
    ProcessLimits sandboxLimits = limits;
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    const unsigned threads = r.threads > 0 ? static_cast<unsigned>(r.threads) : cores;
    sandboxLimits.cpuSeconds = limits.wallSeconds * threads;
    sandboxLimits.fileBytes = 64LL << 20;
    // Threads count as processes: 64 for the viewer's own (bubblewrap, the window-less render
    // thread, TBB's helpers) beside one per render thread, so a node of 64 cores or more can
    // render on all of them.
    sandboxLimits.processes = 64 + threads;
    SandboxOutcome outcome = runInSandbox(run, sandboxLimits, r.runner->sandbox);
    process = outcome.process;
    if (!process.succeeded()) return "";
    if (!outcome.problem.empty()) return outcome.problem;
    for (const std::string& name : run.collect) {
        const auto file = outcome.files.find(name);
        if (file == outcome.files.end()) return "it wrote no " + name;
        std::ofstream(r.scratch + "/" + name, std::ios::binary) << file->second;
    }
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
        if (read.width != r.width || read.height != r.height)
            throw std::runtime_error("the image is " + std::to_string(read.width) + "x" +
                                     std::to_string(read.height) + ", not the size asked for");
        rendered.rgb = read.rgb;
    } catch (const std::exception& e) {
        kind = "unreadable output";
        return std::string("its output could not be read: ") + e.what();
    }
    return "";
}

} // namespace

RenderResult renderLab(const RenderRequest& r, const ProcessLimits& limits) {
    RenderResult result;
    for (int k = 0; k < r.seeds; ++k) {
        const auto [image, stats] = outputNames(r, r.seed + static_cast<uint64_t>(k));
        fs::remove(r.scratch + "/" + image);
        fs::remove(r.scratch + "/" + stats);
    }
    fs::remove(r.scratch + "/" + ReplayFile);
    std::string problem;
    if (r.runner->sandboxed()) {
        problem = renderSandboxed(r, limits, result.process);
    } else {
        std::vector<std::string> argv = {r.runner->viewer};
        const auto arguments = viewerArguments(
            r, r.scratch + "/render.pfm", r.scratch + "/render.json", r.scratch + "/" + ReplayFile);
        argv.insert(argv.end(), arguments.begin(), arguments.end());
        ProcessOptions options;
        options.cpus = r.runner->cpus;
        result.process = runProcess(argv, limits, options);
    }
    if (!result.process.succeeded()) {
        const ProcessOutcome& p = result.process;
        result.failure = p.describe();
        result.failureKind = p.timedOut      ? "time limit"
                             : p.signal != 0 ? "crashed"
                             : result.failure.find("memory") != std::string::npos
                                 ? "out of memory"
                                 : "exited with an error";
        const std::string printed = result.process.outputTail(8);
        if (!printed.empty()) result.failure += "; it printed: " + printed;
        return result;
    }
    if (!problem.empty()) {
        result.failureKind = "unreadable output";
        result.failure = "its output could not be read: " + problem;
        return result;
    }
    for (int k = 0; k < r.seeds; ++k) {
        result.failure = readRendered(r, r.seed + static_cast<uint64_t>(k),
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
    result.width = r.width;
    result.height = r.height;
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

} // namespace pathlab::grader
