// viewer: PathLab's renderer. With -o it renders headless and writes an image; without, it opens
// the progressive window. Run `viewer --help` for the options.
#include "map_files.h"
#include "map_options.h"
#include "reference_figures.h"
#include "viewer_window.h"
#include "window_options.h"

#include "runner/headless_render.h"
#include "runner/pick_test_run.h"
#include "runner/pixel_replay.h"
#include "runner/strategy_figure.h"
#include "runner/warp_test_run.h"

#include "pathlab/images/image_io.h"
#include "pathlab/inspect/inspection_json.h"
#include "pathlab/support/input_error.h"
#include "pathlab/images/pixel_efficiency_map.h"
#include "pathlab/images/pixel_noise_map.h"
#include "pathlab/images/relative_error_map.h"
#include "pathlab/support/program_main.h"
#include "pathlab/render/render_options.h"
#include "pathlab/render/scene_from_options.h"
#include "pathlab/render/render_scene.h"
#include "pathlab/support/whole_file.h"

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace {

using namespace pathlab;
using pathlab::viewer::MapOptions;
using pathlab::viewer::WindowOptions;

/// Checks output paths before any rendering, so a typo costs nothing and leaves nothing behind.
void checkOutputs(const RenderOptions& options, const WindowOptions& window) {
    if (!options.outputImage.empty()) checkImageOutputPath(options.outputImage, "-o");
    if (!window.screenshot.empty()) checkImageOutputPath(window.screenshot, "--screenshot");
    if (!window.windowCapture.empty())
        checkImageOutputPath(window.windowCapture, "--capture-window");
    if (!options.statsFile.empty()) {
        namespace fs = std::filesystem;
        fs::path folder = fs::path(options.statsFile).parent_path();
        if (folder.empty()) folder = ".";
        if (!fs::is_directory(folder))
            throw InputError("option --stats: folder '" + folder.string() + "' does not exist");
    }
}

/// "render.exr" for seed 7 of several: "render-7.exr".
std::string withSeed(const std::string& path, uint64_t seed) {
    const std::filesystem::path p(path);
    return (p.parent_path() /
            (p.stem().string() + "-" + std::to_string(seed) + p.extension().string()))
        .string();
}

/// "noise 0.0123, efficiency 4.56"; with NaN or infinite samples, which are left out of the
/// image, the two describe a different image from the lab's and are not given as figures.
std::string noiseFigures(const RenderStats& s) {
    if (s.nonfinitePixels > 0)
        return "noise and efficiency not meaningful: NaN or infinite samples (see the warning)";
    char text[96];
    std::snprintf(text, sizeof text, "noise %.4f, efficiency %s", s.noise,
                  s.efficiencyText().c_str());
    return text;
}

/// What a headless render writes and prints besides its image: the figures against --reference
/// and the maps asked for, the reference read (and its size checked) before anything renders.
struct HeadlessExtras {
    MapOptions maps;
    std::string referenceFile;
    Image reference;
};

/// The maps of one render, each file the extras name (with the seed's suffix for --seeds);
/// returns the lines to print.
std::vector<std::string> writeMaps(const HeadlessExtras& extras, const RenderOptions& options,
                                   const HeadlessResult& result) {
    const auto named = [&](const std::string& path) {
        return options.seedCount > 1 ? withSeed(path, options.seed) : path;
    };
    std::vector<std::string> lines;
    const std::vector<float> image = result.image.meanImage();
    if (!extras.maps.errorImages.empty()) {
        const std::vector<float> error = relativeErrorMap(image, extras.reference.rgb);
        for (const std::string& path : extras.maps.errorImages)
            lines.push_back(viewer::writeMapFile(
                named(path), options.width, options.height, error,
                "relative squared error against " + extras.referenceFile, extras.maps.range));
    }
    if (!extras.maps.noiseImages.empty() || !extras.maps.efficiencyImages.empty()) {
        std::vector<float> variance;
        result.image.varianceImage(variance);
        const std::vector<float> noise =
            relativeStandardErrorMap(image, variance, result.image.samplesPerPixel());
        for (const std::string& path : extras.maps.noiseImages)
            lines.push_back(viewer::writeMapFile(named(path), options.width, options.height, noise,
                                                 "relative standard error per pixel",
                                                 extras.maps.range));
        // Charged by CPU time, as the panel's and --stats' efficiency; wall-clock time where no
        // CPU time was measured.
        const bool byCpu = result.stats.cpuSeconds > 0;
        const std::vector<float> efficiency =
            efficiencyMap(noise, byCpu ? result.stats.cpuSeconds : result.stats.seconds);
        for (const std::string& path : extras.maps.efficiencyImages)
            lines.push_back(
                viewer::writeMapFile(named(path), options.width, options.height, efficiency,
                                     std::string("efficiency per pixel, 1/(relative variance x ") +
                                         (byCpu ? "CPU-seconds" : "seconds") + " per sample)",
                                     extras.maps.range));
    }
    return lines;
}

int renderToFile(const RenderOptions& options, const HeadlessExtras& extras,
                 const RenderScene& scene) {
    for (int k = 0; k < options.seedCount; ++k) {
        RenderOptions one = options;
        one.seed = options.seed + static_cast<uint64_t>(k);
        if (options.seedCount > 1) {
            one.outputImage = withSeed(options.outputImage, one.seed);
            if (!options.statsFile.empty()) one.statsFile = withSeed(options.statsFile, one.seed);
        }
        HeadlessResult result = renderHeadless(one, scene);
        if (!extras.referenceFile.empty())
            result.stats.reference = viewer::compareWithReference(
                extras.referenceFile, result.image.meanImage(), extras.reference);
        // A lab's NaN is what a student must hear of first: the warning comes before the figures.
        if (result.stats.nonfinitePixels > 0)
            std::fprintf(stderr, "%s\n", result.stats.nonfiniteWarning().c_str());
        writeImage(one.outputImage, one.width, one.height, result.image.meanImage());
        if (!one.statsFile.empty()) writeRenderStats(one.statsFile, result.stats);
        const RenderStats& s = result.stats;
        std::printf("wrote %s: %s, lab %s (%s), %dx%d, %d spp in %.3f s (%.3f s of CPU time)\n"
                    "  %.3g samples/s = %.3g frames/s at %dx%d (1 spp per frame), %.3g rays/s; "
                    "%.3g samples per CPU-second; %s\n",
                    one.outputImage.c_str(), s.scene.c_str(), s.lab.c_str(), s.impl.c_str(),
                    s.width, s.height, s.spp, s.seconds, s.cpuSeconds, s.samplesPerSecond(),
                    s.framesPerSecond, s.width, s.height, s.raysPerSecond(),
                    s.samplesPerCpuSecond(), noiseFigures(s).c_str());
        // In parentheses, not "note:": those are the scene's notes, which tests count.
        for (const std::string& said : {s.busyNote(), s.cpuNote()})
            if (!said.empty()) std::printf("  (%s)\n", said.c_str());
        if (s.reference) std::printf("%s\n", viewer::referenceLine(*s.reference).c_str());
        for (const std::string& line : writeMaps(extras, one, result))
            std::printf("%s\n", line.c_str());
        std::fflush(stdout);
    }
    return 0;
}

/// --inspect: the pixel's paths, as a table or into --inspect-out's JSON.
void inspectPixel(const RenderOptions& options, const RenderScene& scene) {
    const PixelReplay replay = replayPixel(options, scene);
    const bool toFile = !options.inspectOut.empty();
    if (toFile) {
        writeFileAtomically(options.inspectOut,
                            inspectionJson(replay.lab,
                                           replay.reference ? &*replay.reference : nullptr,
                                           replay.comparison ? &*replay.comparison : nullptr));
        std::printf("wrote %s: %zu sample(s) of pixel (%d, %d), lab %s%s\n",
                    options.inspectOut.c_str(), replay.lab.samples.size(), options.inspectX,
                    options.inspectY, labAndImplementation(replay.lab.identity).c_str(),
                    replay.reference ? " beside the reference solution's" : "");
    }
    std::printf("%s", pixelReplayText(replay, !toFile).c_str());
    std::fflush(stdout);
}

/// --pick-test: the lab's picks against its divisions; 1 when they differ.
int testPicks(const RenderOptions& options, const RenderScene& scene) {
    std::printf("pick test of lab %s on %dx%d pixels, %d samples each ...\n",
                labAndImplementation(options).c_str(), PickTestGrid, PickTestGrid, PickTestSamples);
    std::fflush(stdout);
    const PickTestResult result = runPickTest(options, scene);
    std::printf("%s", describePickTest(result).c_str());
    return result.passed ? 0 : 1;
}

/// --warp-test: the lab's sampleLobe against its lobePdf; 1 when they disagree.
int testWarp(const RenderOptions& options) {
    if (!options.warpImage.empty()) checkImageOutputPath(options.warpImage, "--warp-image");
    lobeRoutinesToTest(options.lab, options.implementation);
    std::printf("warp test of lab %s: %llu directions at each exponent ...\n",
                labAndImplementation(options).c_str(),
                static_cast<unsigned long long>(options.warpSamples));
    std::fflush(stdout);
    const LabWarpTests tests =
        runLabWarpTests(options.lab, options.implementation, options.seed + 1, options.warpSamples,
                        options.watchdogSeconds);
    std::printf("%s", describeLabWarpTests(tests).c_str());
    if (!options.warpImage.empty()) {
        writeWarpTestImage(options.warpImage, tests);
        std::printf("wrote %s: a row per exponent (1, 12, 60 from the top); in each, theta from "
                    "the lobe's axis down (0 to 180 degrees) and phi across: the samples "
                    "counted, lobePdf's expectation, and their difference (blue: fewer than "
                    "expected, red: more)\n",
                    options.warpImage.c_str());
    }
    return tests.passed ? 0 : 1;
}

/// --strategy-figure: lab 6's three renders, light alone, lobe alone and both, side by side.
void drawStrategyFigure(const RenderOptions& options, const RenderScene& scene) {
    std::printf("lab %s with each strategy alone and both, %dx%d at %d spp ...\n",
                labAndImplementation(options).c_str(), options.width, options.height, options.spp);
    std::fflush(stdout);
    const std::vector<StrategyPanel> panels = renderStrategyPanels(options, scene);
    writeStrategyFigure(options.strategyFigure, panels, options.width, options.height);
    std::printf("wrote %s: light alone, lobe alone and both, left to right\n%s",
                options.strategyFigure.c_str(), describeStrategyPanels(panels).c_str());
}

/// The headless runs: -o's render, --inspect's replay, --pick-test, --strategy-figure, or several
/// (in that order).
int runHeadless(const RenderOptions& options, const HeadlessExtras& extras) {
    const RenderScene scene(loadScene(options));
    if (!options.strategyFigure.empty()) drawStrategyFigure(options, scene);
    if (!options.outputImage.empty()) renderToFile(options, extras, scene);
    if (options.inspect) inspectPixel(options, scene);
    return options.pickTest ? testPicks(options, scene) : 0;
}

} // namespace

int main(int argc, char** argv) {
    return runMain("viewer", [&] {
        WindowOptions window;
        HeadlessExtras extras;
        ExtraOptions readers = viewer::windowOptionReaders(window);
        readers.merge(viewer::mapOptionReaders(extras.maps));
        const RenderOptions options = parseRenderOptions(argc, argv, readers);
        viewer::completeWindowOptions(window);
        if (options.help) {
            std::printf("usage: viewer -c SCENE.ecs [options]\n\n%s%s%s"
                        "Single-dash spellings (-vp, -size, ...) work too, as in .ecs files.\n",
                        renderOptionsHelp().c_str(), viewer::windowOptionsHelp(),
                        viewer::mapOptionsHelp());
            return 0;
        }
        if (options.warpTest) return testWarp(options);
        if (!options.lobeDump.empty()) {
            writeLobeDump(options.lobeDump, options.lab, options.implementation, options.seed,
                          options.watchdogSeconds);
            return 0;
        }
        if (options.objFiles.empty())
            throw InputError("no scene given: use -c FILE.ecs or -i FILE.obj (viewer --help)");
        checkOutputs(options, window);
        viewer::checkMapOptions(extras.maps, options, window);
        checkInspectOptions(options);
        viewer::checkInspectWindow(window, options);
        if (!options.strategyFigure.empty())
            checkImageOutputPath(options.strategyFigure, "--strategy-figure");
        if (!options.outputImage.empty() || options.pickTest || !options.strategyFigure.empty() ||
            (options.inspect && !window.inspectInWindow)) {
            if (!options.outputImage.empty() && !window.referenceImage.empty()) {
                extras.referenceFile = window.referenceImage;
                extras.reference = viewer::readReferenceOfSize(window.referenceImage, options.width,
                                                               options.height);
            }
            return runHeadless(options, extras);
        }
        return runViewerWindow(options, window);
    });
}
