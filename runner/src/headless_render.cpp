#include "runner/headless_render.h"

#include "runner/lab_tables.h"

#include "pathlab/render/scene_from_options.h"
#include "pathlab/scene_io/camera.h"
#include "pathlab/render/render_progress_line.h"
#include "pathlab/render/render_scene.h"
#include "pathlab/render/lab_crash_line.h"
#include "pathlab/render/render_watchdog.h"
#include "pathlab/render/renderer.h"

#include <chrono>
#include <optional>

namespace pathlab {

HeadlessResult renderHeadless(const RenderOptions& options) {
    const RenderScene scene(loadScene(options));
    return renderHeadless(options, scene);
}

HeadlessResult renderHeadless(const RenderOptions& options, const RenderScene& scene) {
    const Camera camera(scene.scene().camera.value_or(scene.scene().framingCamera()), options.width,
                        options.height);
    Renderer renderer(scene, options.threads);
    renderer.setReverseTiles(options.reverseTiles);
    HeadlessResult result{AccumulationBuffer(options.width, options.height), {}};

    const WatchedLab watched{options.lab, options.implementation};
    // From the start: the lab's code is loaded below (findPathTrace), and may hang as it loads.
    const RenderWatchdog watchdog(
        renderer.progress(), options.watchdogSeconds, [watched] { return watched; }, true);
    // A lab that crashes the render (a recursion that never ends) is named as a stuck one is.
    const LabCrashLine crashLine(watched);
    const auto start = std::chrono::steady_clock::now();
    {
        // A render into a file (viewer -o) shows its progress; the lab tests' renders, which
        // write none, leave the test runner's output alone.
        std::optional<RenderProgressLine> progressLine;
        if (!options.outputImage.empty())
            progressLine.emplace(renderer.progress(), options.outputImage);
        renderer.renderPass(result.image, camera,
                            findPathTrace(options.lab, options.implementation), options.parameters,
                            options.seed, options.spp);
    }
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;

    result.stats = renderStats({options, options.sceneName}, result.image, renderer.threads(),
                               elapsed.count(), renderer.rayCounters(), renderer.firstNonfinite(),
                               {renderer.cpuSeconds(), renderer.processCpuSeconds()});
    setHeadlessFrameRate(result.stats);
    return result;
}

} // namespace pathlab
