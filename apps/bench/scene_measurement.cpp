#include "scene_measurement.h"

#include "pathlab/render/render_options.h"
#include "pathlab/render/scene_from_options.h"

namespace pathlab::bench {

namespace {

/// Replays of a few hundred milliseconds each: the fastest of three is stable to a few percent.
constexpr int ReplayRepeats = 3;

} // namespace

TraversalTimes SceneFigures::raw() const {
    TraversalTimes total;
    for (const SolutionFigures& s : solutions) total += s.raw;
    return total;
}

TraversalTimes SceneFigures::rawOneThread() const {
    TraversalTimes total;
    for (const SolutionFigures& s : solutions) total += s.rawOneThread;
    return total;
}

SceneFigures measureScene(const BenchScene& benchScene, const SceneSettings& settings) {
    const RenderOptions options = renderOptionsFor(benchScene, settings.width, settings.height);
    const RenderScene scene(loadScene(options));
    const Camera camera = sceneCamera(scene, settings.width, settings.height);

    SceneFigures figures;
    figures.name = benchScene.name;
    figures.triangles = scene.scene().triangles.size();
    figures.settings = settings;
    for (Lab lab : AllLabs) {
        const RenderJob job =
            solutionJob(scene, camera, lab, settings.parameters, settings.width, settings.height);
        SolutionFigures s{lab, {}, {}, {}, {}};
        s.render = timeRender(job, settings.spp, settings.passes, settings.threads);
        s.renderOneThread = timeRender(job, settings.spp, settings.passes, 1);
        const RayLog log = recordRays(job, settings.threads);
        s.raw = timeTraversal(scene, log, settings.threads, ReplayRepeats);
        s.rawOneThread = timeTraversal(scene, log, 1, ReplayRepeats);
        figures.solutions.push_back(s);
    }
    return figures;
}

} // namespace pathlab::bench
