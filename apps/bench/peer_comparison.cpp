#include "peer_comparison.h"

#include "bench_scene.h"
#include "embree_pathtracer.h"
#include "render_timing.h"

#include "process/child_process.h"

#include "pathlab/render/scene_from_options.h"
#include "pathlab/render/accumulation_buffer.h"
#include "pathlab/render/renderer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <unistd.h>

namespace pathlab::bench {

namespace {

/// The mean of an RGB image after Embree's 8-bit storage, per channel.
Color storedMean(const std::vector<float>& rgb, bool alreadyStored) {
    double sum[3] = {0, 0, 0};
    for (size_t i = 0; i < rgb.size(); ++i)
        sum[i % 3] += alreadyStored ? rgb[i] : embreeStoredValue(rgb[i]);
    const double pixels = static_cast<double>(rgb.size() / 3);
    return {static_cast<float>(sum[0] / pixels), static_cast<float>(sum[1] / pixels),
            static_cast<float>(sum[2] / pixels)};
}

/// Embree's pathtracer and PathLab's solution, timed in turn for c.rounds rounds, the best of
/// each by each clock: a busy moment of the machine then slows one round of one of them, not the
/// ratio.
void timeInTurns(const PathtracerJob& embree, const RenderJob& job, int threads, int pathLength,
                 PeerComparison& c) {
    for (int round = 0; round < c.rounds; ++round) {
        const PathtracerSpeed theirs = pathtracerSpeed(embree, c.spp, c.frames);
        c.embreeSamplesPerSecond = std::max(c.embreeSamplesPerSecond, theirs.samplesPerSecond);
        c.embreeCpuSecondsPerFrame.push_back(theirs.cpuSecondsPerFrame);
        if (round == 0) c.embreeStartCpuSeconds = theirs.startCpuSeconds;
        if (theirs.samplesPerCpuSecond > c.embreeSamplesPerCpuSecond) {
            c.embreeSamplesPerCpuSecond = theirs.samplesPerCpuSecond;
            c.embreeStartCpuSeconds = theirs.startCpuSeconds;
            c.embreeCpuUse = {"Embree's pathtracer at path length " + std::to_string(pathLength),
                              theirs.cpuSecondsPerFrame,
                              theirs.framesPerSecond > 0 ? 1 / theirs.framesPerSecond : 0, threads};
        }
        // The process's CPU time, not only the render threads' tiles: the pathtracer's figure
        // is its whole process's, its threads' waits for work included (here the two differ
        // by under 0.3%).
        const RenderTiming ours = timeRender(job, c.spp, c.frames, threads);
        c.oursSamplesPerSecond = std::max(c.oursSamplesPerSecond, ours.samplesPerSecond());
        const double oursPerCpuSecond =
            RenderTiming::perSecond(ours.samples, ours.processCpuSeconds);
        if (oursPerCpuSecond > c.oursSamplesPerCpuSecond) {
            c.oursSamplesPerCpuSecond = oursPerCpuSecond;
            c.oursCpuUse = {"PathLab's passes at path length " + std::to_string(pathLength),
                            ours.processCpuSeconds, ours.seconds, threads};
        }
    }
}

/// The two images' means, Embree's as it stores them and ours stored the same way, with the
/// standard error of their difference.
void compareImages(const PathtracerJob& embree, const RenderScene& ours, const Camera& camera,
                   const RenderJob& job, const LabParameters& parameters, int threads,
                   PeerComparison& c) {
    const std::string folder =
        (std::filesystem::temp_directory_path() / ("pathlab-bench-" + std::to_string(::getpid())))
            .string();
    std::filesystem::create_directories(folder);
    const std::vector<float> embreeImage = pathtracerImage(embree, c.imageSpp, folder);
    std::filesystem::remove_all(folder);
    c.embreeMean = storedMean(embreeImage, true);

    Renderer renderer(ours, threads);
    AccumulationBuffer image(c.width, c.height);
    renderer.renderPass(image, camera, job.pathTrace, parameters, 0, c.imageSpp);
    const std::vector<float> rgb = image.meanImage();
    c.oursMean = storedMean(rgb, false);
    c.oursMaxPixel = *std::max_element(rgb.begin(), rgb.end());

    // Each image mean has variance (mean per-sample variance) / (pixels × spp); the two are
    // independent estimates of the same value with the same estimator, so their difference has
    // twice that variance. The 8-bit storage adds a negligible amount.
    const Color variance = image.summary().meanVariance;
    const float n = static_cast<float>(c.width) * static_cast<float>(c.height) * c.imageSpp;
    c.standardError = {std::sqrt(2 * variance.r / n), std::sqrt(2 * variance.g / n),
                       std::sqrt(2 * variance.b / n)};
}

} // namespace

PeerComparison comparePeer(const BenchOptions& options, int threads, int pathLength) {
    PeerComparison c;
    c.scene = std::filesystem::path(options.peerScene).stem().string();
    c.width = options.width;
    c.height = options.height;
    c.spp = options.peerSpp;
    c.frames = options.passes;
    c.rounds = 3;
    c.imageSpp = options.peerImageSpp;
    c.threads = threads;
    c.maxPathLength = pathLength;
    c.lightScale = options.peerLightScale;

    const std::string program = options.pathtracer.empty() ? "" : findProgram(options.pathtracer);
    if (program.empty()) {
        c.note = options.pathtracer.empty() ? "skipped (--no-pathtracer)"
                                            : "Embree's '" + options.pathtracer +
                                                  "' was not found (Debian package embree-tools)";
        return c;
    }
    if (!std::filesystem::is_regular_file(options.peerScene)) {
        c.note = options.peerScene + " was not found (Debian package embree-tools)";
        return c;
    }

    // Said here, past the reasons to skip: the progress line names only what is measured.
    std::fprintf(stderr, "bench: Embree's pathtracer at path length %d ...\n", pathLength);
    const BenchScene scene = peerSceneFromFile(options.peerScene, options.peerLightScale);
    const PathtracerJob embree{program, scene, c.width, c.height, c.maxPathLength, threads};

    const RenderScene ours(loadScene(renderOptionsFor(scene, c.width, c.height)));
    const Camera camera = sceneCamera(ours, c.width, c.height);
    LabParameters parameters = options.parameters;
    parameters.maxDepth = pathLength - 1;
    const RenderJob job = solutionJob(ours, camera, Lab::Importance, parameters, c.width, c.height);
    timeInTurns(embree, job, threads, pathLength, c);

    if (!(c.embreeSamplesPerCpuSecond > 0)) {
        char text[240];
        std::snprintf(text, sizeof text,
                      "Embree's %d frame(s) took too little CPU time (%.3g s) to time by "
                      "difference from its start-up: raise --peer-spp",
                      c.frames,
                      *std::max_element(c.embreeCpuSecondsPerFrame.begin(),
                                        c.embreeCpuSecondsPerFrame.end()) *
                          c.frames);
        c.cpuNote = text;
    }

    compareImages(embree, ours, camera, job, parameters, threads, c);
    c.measured = true;
    return c;
}

} // namespace pathlab::bench
