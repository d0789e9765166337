// viewer: PathLab's renderer. With -o it renders headless and writes an image; without, it opens
// the progressive window. Run `viewer --help` for the options.
#include "pathlab/headless_render.h"
#include "pathlab/image_io.h"
#include "pathlab/input_error.h"
#include "pathlab/render_options.h"
#include "pathlab/render_scene.h"
#include "viewer_window.h"

#include <cstdio>
#include <exception>
#include <filesystem>

namespace {

using namespace pathlab;

/// Checks output paths before any rendering, so a typo costs nothing and leaves nothing behind.
void checkOutputs(const RenderOptions& options) {
    if (!options.outputImage.empty()) checkImageOutputPath(options.outputImage, "-o");
    if (!options.screenshot.empty()) checkImageOutputPath(options.screenshot, "--screenshot");
    if (!options.windowCapture.empty())
        checkImageOutputPath(options.windowCapture, "--capture-window");
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
    return (p.parent_path() / (p.stem().string() + "-" + std::to_string(seed) + p.extension().string())).string();
}

int renderToFile(const RenderOptions& options) {
    const RenderScene scene(loadScene(options));
    for (int k = 0; k < options.seedCount; ++k) {
        RenderOptions one = options;
        one.seed = options.seed + static_cast<uint64_t>(k);
        if (options.seedCount > 1) {
            one.outputImage = withSeed(options.outputImage, one.seed);
            if (!options.statsFile.empty()) one.statsFile = withSeed(options.statsFile, one.seed);
        }
        HeadlessResult result = renderHeadless(one, scene);
        writeImage(one.outputImage, one.width, one.height, result.image.meanImage());
        if (!one.statsFile.empty()) writeRenderStats(one.statsFile, result.stats);
        const RenderStats& s = result.stats;
        std::printf("wrote %s: %s, lab %s (%s), %dx%d, %d spp in %.3f s\n"
                    "  %.3g samples/s = %.3g frames/s at %dx%d (1 spp per frame), %.3g rays/s; "
                    "noise %.4f, efficiency %s\n",
                    one.outputImage.c_str(), s.scene.c_str(), s.lab.c_str(), s.impl.c_str(),
                    s.width, s.height, s.spp, s.seconds, s.samplesPerSecond(), s.framesPerSecond,
                    s.width, s.height, s.raysPerSecond(), s.noise, s.efficiencyText().c_str());
        if (s.nonfinitePixels > 0) std::fprintf(stderr, "%s\n", s.nonfiniteWarning().c_str());
    }
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    try {
        const RenderOptions options = parseRenderOptions(argc, argv);
        if (options.help) {
            std::fputs(renderOptionsHelp(), stdout);
            return 0;
        }
        if (options.objFiles.empty())
            throw InputError("no scene given: use -c FILE.ecs or -i FILE.obj (viewer --help)");
        checkOutputs(options);
        if (!options.outputImage.empty()) return renderToFile(options);
        return runViewerWindow(options);
    } catch (const InputError& error) {
        std::fprintf(stderr, "viewer: %s\n", error.what());
        return 2;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "viewer: error: %s\n", error.what());
        return 1;
    }
}
