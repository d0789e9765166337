#include "pathlab/headless_render.h"

#include "pathlab/camera.h"
#include "pathlab/render_scene.h"
#include "pathlab/renderer.h"

#include <chrono>

namespace pathlab {

HeadlessResult renderHeadless(const RenderOptions& options) {
    const RenderScene scene(loadScene(options));
    return renderHeadless(options, scene);
}

HeadlessResult renderHeadless(const RenderOptions& options, const RenderScene& scene) {
    const Camera camera(scene.scene().camera.value_or(scene.scene().framingCamera()), options.width,
                        options.height);
    Renderer renderer(scene, options.threads);
    HeadlessResult result{AccumulationBuffer(options.width, options.height), {}};

    const auto start = std::chrono::steady_clock::now();
    renderer.renderPass(result.image, camera, findPathTrace(options.lab, options.implementation),
                        options.parameters, options.seed, options.spp);
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;

    RenderStats& s = result.stats;
    s.scene = options.sceneName;
    s.lab = labName(options.lab);
    s.impl = implementationName(options.implementation);
    s.spp = options.spp;
    s.width = options.width;
    s.height = options.height;
    s.seed = options.seed;
    s.maxDepth = options.parameters.maxDepth;
    s.continueProb = options.parameters.continueProb;
    s.threads = renderer.threads();
    s.seconds = elapsed.count();
    s.rays = renderer.rayCounters();
    const AccumulationBuffer::Summary summary = result.image.summary();
    s.meanRadiance = summary.meanRadiance;
    s.meanVariance = summary.meanVariance;
    s.nonfinitePixels = summary.nonfinitePixels;
    s.noise = summary.noise;
    setHeadlessFrameRate(s);
    return result;
}

} // namespace pathlab
