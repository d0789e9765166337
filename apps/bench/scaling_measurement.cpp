#include "scaling_measurement.h"

#include "pathlab/render/accumulation_buffer.h"
#include "pathlab/render/render_options.h"
#include "pathlab/render/scene_from_options.h"

#include <algorithm>
#include <chrono>
#include <set>

namespace pathlab::bench {

namespace {

/// The fastest of `repeats` calls of f, in seconds.
template <typename F> double fastestSeconds(int repeats, const F& f) {
    double best = 0;
    for (int i = 0; i < repeats; ++i) {
        const auto start = std::chrono::steady_clock::now();
        f();
        const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
        if (i == 0 || elapsed.count() < best) best = elapsed.count();
    }
    return best;
}

} // namespace

double ScalingFigures::handOffShare(int threads) const {
    const auto at = [&](int t) {
        for (const Point& p : byThreads)
            if (p.value == t) return p.samplesPerSecond();
        return 0.0;
    };
    const double one = at(1), measured = at(tileThreads);
    if (one <= 0 || measured <= 0 || tileThreads < 1) return 0;
    // Samples/s per thread as measured at tileThreads, carried on linearly: the best case.
    const double perThread = measured / tileThreads;
    const double passSeconds = double(width) * height / (perThread * threads);
    return handOffSeconds / (handOffSeconds + passSeconds);
}

ScalingFigures measureScaling(const BenchScene& benchScene, const SceneSettings& settings, Lab lab,
                              int cores) {
    const RenderOptions options = renderOptionsFor(benchScene, settings.width, settings.height);
    const RenderScene scene(loadScene(options));
    const Camera camera = sceneCamera(scene, settings.width, settings.height);
    const RenderJob job =
        solutionJob(scene, camera, lab, settings.parameters, settings.width, settings.height);

    ScalingFigures f;
    f.scene = benchScene.name;
    f.lab = lab;
    f.width = settings.width;
    f.height = settings.height;
    f.passes = settings.passes;
    f.tileThreads = cores;
    std::set<int> threadCounts = {1, 2, 4, 8, cores};
    const PassChoice fastest = PassChoice::LeastWallTime;
    for (int threads : threadCounts)
        f.byThreads.push_back(
            {threads, timeRender(job, 1, settings.passes, threads, Renderer::TileSize, fastest)});
    for (int tile : {8, 16, 32, 64})
        f.byTileSize.push_back({tile, timeRender(job, 1, settings.passes, cores, tile, fastest)});

    // The hand-off as the window's render thread does it, on an image of two passes.
    AccumulationBuffer image(settings.width, settings.height);
    Renderer renderer(scene, cores);
    renderer.renderPass(image, camera, job.pathTrace, job.parameters, 0, 2);
    std::vector<float> display;
    f.handOffSeconds = fastestSeconds(std::max(3, settings.passes), [&] {
        const AccumulationBuffer::Summary summary = image.summary();
        image.meanImage(display);
        if (summary.noise < 0) display.clear(); // keeps the summary from being optimised away
    });
    return f;
}

} // namespace pathlab::bench
