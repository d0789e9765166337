#include "checks/kit_ray_cost.h"

#include "pathlab/render/accumulation_buffer.h"
#include "pathlab/scene_io/camera.h"
#include "pathlab/support/cpu_clock.h"
#include "pathlab/path_context.h"
#include "pathlab/scattering.h"
#include "pathlab/render/render_options.h"
#include "pathlab/render/scene_from_options.h"
#include "pathlab/render/render_scene.h"
#include "pathlab/render/renderer.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace pathlab::grader {

namespace {

/// The kit's path tracer: the work every lab does for each ray (a closest hit, the hit's record,
/// next-event estimation, a diffuse direction from the path's sampler), and no lab's choices.
/// Its image is never looked at; only its cost.
Color kitPath(const Ray& ray, int depth, PathContext& ctx) {
    const Hit hit = ctx.trace(ray);
    if (!hit) return Color();
    // (Named unlike the labs' code: the release must hold no line of a solution.)
    const Color found = hit.emitted + ctx.directLight(hit);
    if (depth >= ctx.maxDepth) return found;
    return found + 0.5f * kitPath(diffuseRay(hit, ctx.sampler.get2D()), depth + 1, ctx);
}

/// Renders of at least this much CPU time: far above the clock's step, short beside a grading.
constexpr double LeastCpuSeconds = 0.1;
constexpr int Renders = 3;

} // namespace

double kitCpuSecondsPerRay(const std::string& ecsFile, int width, int height, int threads) {
    const char* argv[] = {"grader", "-c", ecsFile.c_str()};
    RenderOptions options = parseRenderOptions(3, argv);
    options.width = width;
    options.height = height;
    const RenderScene scene(loadScene(options));
    const Camera camera(scene.scene().camera.value_or(scene.scene().framingCamera()), width,
                        height);
    Renderer renderer(scene, threads);
    LabParameters parameters;
    parameters.maxDepth = 3;
    std::vector<double> perRay;
    int spp = 1;
    for (uint64_t seed = 0; perRay.size() < Renders && seed < 16; ++seed) {
        AccumulationBuffer image(width, height);
        renderer.resetCounts();
        renderer.renderPass(image, camera, kitPath, parameters, seed, spp);
        // The process's CPU time, as the timed runs count a render: the threads' waiting for
        // work included.
        const double cpu = renderer.processCpuSeconds();
        const double rays = static_cast<double>(renderer.rayCounters().total());
        if (cpu < LeastCpuSeconds) {
            // Too short to time (the first is): enough samples for the next to be long enough.
            spp = std::min(4096, static_cast<int>(
                                     std::ceil(spp * 1.3 * LeastCpuSeconds / std::max(cpu, 1e-4))));
            continue;
        }
        perRay.push_back(cpu / rays);
    }
    if (perRay.empty()) return 0;
    std::sort(perRay.begin(), perRay.end());
    return perRay[perRay.size() / 2];
}

} // namespace pathlab::grader
