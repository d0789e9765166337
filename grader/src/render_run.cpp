#include "render_run.h"

#include "pathlab/image_io.h"
#include "pathlab/input_error.h"
#include "pathlab/render_options.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <thread>

namespace pathlab::grader {

namespace {

namespace fs = std::filesystem;

std::vector<std::string> viewerArguments(const RenderRequest& r, const std::string& image,
                                         const std::string& stats) {
    std::vector<std::string> argv = {
        "-c", r.scene, "--size", std::to_string(r.width), std::to_string(r.height),
        "--spp", std::to_string(r.spp), "--lab", std::string(labName(r.lab)),
        "--max-depth", std::to_string(r.maxDepth), "--continue-prob", std::to_string(r.continueProb),
        "--seed", std::to_string(r.seed), "-o", image, "--stats", stats};
    if (!r.runner->sandboxed() && r.runner->implementation == Implementation::Solution)
        argv.push_back("--solution");
    if (r.threads > 0) argv.insert(argv.end(), {"--threads", std::to_string(r.threads)});
    return argv;
}

/// Runs the submission viewer in the sandbox and puts the image and stats it leaves into
/// `image` and `stats` on the host. Returns a problem in words, or "".
std::string renderSandboxed(const RenderRequest& r, const ProcessLimits& limits,
                            const std::string& image, const std::string& stats,
                            ProcessOutcome& process) {
    SandboxRun run;
    run.command = {"/pathlab/viewer"};
    const auto arguments = viewerArguments(r, "render.exr", "render.json");
    run.command.insert(run.command.end(), arguments.begin(), arguments.end());
    run.files = {{r.runner->viewer, "/pathlab/viewer"}, {r.runner->labsLibrary, "/pathlab/labs.so"}};
    for (const std::string& file : sceneFiles(r.scene)) run.files.push_back({file, file});
    run.environment = {{"PATHLAB_LABS_LIBRARY", "/pathlab/labs.so"}};
    run.collect = {"render.exr", "render.json"};
    run.scratchBytes = 64LL << 20;
    ProcessLimits sandboxLimits = limits;
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    sandboxLimits.cpuSeconds = limits.wallSeconds * (r.threads > 0 ? r.threads : cores);
    sandboxLimits.fileBytes = 64LL << 20;
    sandboxLimits.processes = 64;
    SandboxOutcome outcome = runInSandbox(run, sandboxLimits, r.runner->sandbox);
    process = outcome.process;
    if (!process.succeeded()) return "";
    if (!outcome.problem.empty()) return outcome.problem;
    for (const auto& [name, path] : {std::pair{"render.exr", image}, {"render.json", stats}}) {
        const auto file = outcome.files.find(name);
        if (file == outcome.files.end()) return std::string("it wrote no ") + name;
        std::ofstream(path, std::ios::binary) << file->second;
    }
    return "";
}

} // namespace

RenderResult renderLab(const RenderRequest& r, const ProcessLimits& limits) {
    RenderResult result;
    const std::string image = r.scratch + "/render.exr", stats = r.scratch + "/render.json";
    fs::remove(image);
    fs::remove(stats);
    std::string problem;
    if (r.runner->sandboxed()) {
        problem = renderSandboxed(r, limits, image, stats, result.process);
    } else {
        std::vector<std::string> argv = {r.runner->viewer};
        const auto arguments = viewerArguments(r, image, stats);
        argv.insert(argv.end(), arguments.begin(), arguments.end());
        ProcessOptions options;
        options.cpus = r.runner->cpus;
        result.process = runProcess(argv, limits, options);
    }
    if (!result.process.succeeded()) {
        const ProcessOutcome& p = result.process;
        result.failure = p.describe();
        result.failureKind = p.timedOut ? "time limit" : p.signal != 0 ? "crashed"
                           : result.failure.find("memory") != std::string::npos ? "out of memory"
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
    try {
        std::ifstream in(stats);
        const nlohmann::json s = nlohmann::json::parse(in);
        result.nonfinitePixels = s.at("nonfinite_pixels");
        for (int c = 0; c < 3; ++c) result.meanVariance[c] = s.at("mean_variance").at(c);
        const Image read = readImage(image);
        // The lab runs in the process that writes this file: what it holds is checked, not trusted.
        if (read.width != r.width || read.height != r.height)
            throw std::runtime_error("the image is " + std::to_string(read.width) + "x" +
                                     std::to_string(read.height) + ", not the size asked for");
        result.image = read.rgb;
        result.width = read.width;
        result.height = read.height;
    } catch (const std::exception& e) {
        result.failureKind = "unreadable output";
        result.failure = std::string("its output could not be read: ") + e.what();
        return result;
    }
    if (result.nonfinitePixels > 0) {
        result.failureKind = "NaN or infinite radiance";
        result.failure = "returned NaN or infinite radiance in " +
                         std::to_string(result.nonfinitePixels) +
                         " pixels (a division by a zero probability?)";
        return result;
    }
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

std::vector<std::string> sceneFiles(const std::string& ecsPath) {
    static std::map<std::string, std::vector<std::string>> known; // scenes do not change mid-grading
    if (const auto found = known.find(ecsPath); found != known.end()) return found->second;
    const char* argv[] = {"viewer", "-c", ecsPath.c_str()};
    const RenderOptions options = parseRenderOptions(3, argv);
    std::vector<std::string> files;
    for (const std::string& script : options.sceneScripts) files.push_back(fs::absolute(script).string());
    // tinyobjloader looks for an .obj's material libraries beside it.
    const std::regex mtllib(R"(^\s*mtllib\s+(.+?)\s*$)");
    for (const std::string& obj : options.objFiles) {
        files.push_back(fs::absolute(obj).string());
        std::ifstream in(obj);
        std::string line;
        std::smatch match;
        while (std::getline(in, line))
            if (line.find("mtllib") != std::string::npos && std::regex_match(line, match, mtllib)) {
                const fs::path mtl = fs::absolute(fs::path(obj).parent_path() / match[1].str());
                if (fs::exists(mtl)) files.push_back(mtl.string());
            }
    }
    return known[ecsPath] = files;
}

} // namespace pathlab::grader
