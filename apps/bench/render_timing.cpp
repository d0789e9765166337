#include "render_timing.h"

#include "runner/lab_tables.h"

#include "pathlab/render/accumulation_buffer.h"
#include "pathlab/render/renderer.h"

#include <chrono>

namespace pathlab::bench {

Camera sceneCamera(const RenderScene& scene, int width, int height) {
    return Camera(scene.scene().camera.value_or(scene.scene().framingCamera()), width, height);
}

RenderJob solutionJob(const RenderScene& scene, const Camera& camera, Lab lab,
                      const LabParameters& parameters, int width, int height) {
    return {scene, camera, findPathTrace(lab, Implementation::Solution), parameters, width, height};
}

RenderTiming timeRender(const RenderJob& job, int spp, int passes, int threads, int tileSize,
                        PassChoice choice) {
    Renderer renderer(job.scene, threads);
    renderer.setTileSize(tileSize);
    AccumulationBuffer image(job.width, job.height);
    const uint64_t seed = 0;
    renderer.renderPass(image, job.camera, job.pathTrace, job.parameters, seed, spp);

    const auto time = [choice](const RenderTiming& t) {
        return choice == PassChoice::LeastCpuTime ? t.cpuSeconds : t.seconds;
    };
    RenderTiming best;
    for (int pass = 0; pass < passes; ++pass) {
        renderer.resetCounts();
        const auto start = std::chrono::steady_clock::now();
        renderer.renderPass(image, job.camera, job.pathTrace, job.parameters, seed, spp);
        const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
        const RenderTiming timing{elapsed.count(),
                                  renderer.cpuSeconds(),
                                  renderer.processCpuSeconds(),
                                  renderer.threads(),
                                  static_cast<long long>(job.width) * job.height * spp,
                                  renderer.rayCounters()};
        if (pass == 0 || time(timing) < time(best)) best = timing;
    }
    return best;
}

RayLog recordRays(const RenderJob& job, int threads) {
    Renderer renderer(job.scene, threads);
    AccumulationBuffer image(job.width, job.height);
    RayLog log;
    renderer.renderPass(image, job.camera, job.pathTrace, job.parameters, 0, 1, nullptr, &log);
    return log;
}

} // namespace pathlab::bench
