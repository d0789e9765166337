// More threads than cores (a lab machine's 16 to 64, or --threads 8 on a laptop): every thread
// the renderer was asked for renders at the same time, and the image stays the seed's.
#include "catch.h"
#include "test_support.h"

#include "pathlab/render/scene_from_options.h"
#include "pathlab/lab.h"
#include "pathlab/render/renderer.h"

#include <chrono>
#include <condition_variable>
#include <cstring>
#include <map>
#include <mutex>
#include <thread>

using namespace pathlab;

namespace {

/// What the threads of one pass did: how many were inside pathTrace at once at most, and the
/// samples each rendered.
struct ThreadRecord {
    std::mutex mutex;
    std::condition_variable arrived;
    int inside = 0, mostInside = 0, waitFor = 0;
    std::map<std::thread::id, int> samples;
};
ThreadRecord* record = nullptr;

/// A lab that notes its thread, and whose first sample on each thread waits (up to 10 s) until
/// `waitFor` threads are inside it at once: with fewer runnable threads than that, the pass is
/// slow and mostInside says how many there were. Its radiance is the surface's own, so the
/// image is the scene's and depends on the seed's jitter alone.
Color threadNotingTrace(const Ray& ray, int, PathContext& ctx) {
    {
        std::unique_lock<std::mutex> lock(record->mutex);
        const bool first = record->samples[std::this_thread::get_id()]++ == 0;
        if (first) {
            record->mostInside = std::max(record->mostInside, ++record->inside);
            record->arrived.notify_all();
            record->arrived.wait_for(lock, std::chrono::seconds(10),
                                     [] { return record->inside >= record->waitFor; });
        }
    }
    const Hit hit = ctx.trace(ray);
    return hit ? hit.material.Kd : Color();
}

std::vector<float> renderWith(int threads, ThreadRecord& r) {
    record = &r;
    r.waitFor = threads;
    const std::string scene = test::modelPath("cornell_box_VI2_Specular.ecs");
    const char* argv[] = {"viewer", "-c", scene.c_str(), "--size", "128", "128"};
    const RenderOptions options = parseRenderOptions(6, argv);
    const RenderScene renderScene(loadScene(options));
    const Camera camera(*renderScene.scene().camera, 128, 128);
    Renderer renderer(renderScene, threads);
    AccumulationBuffer buffer(128, 128);
    renderer.renderPass(buffer, camera, threadNotingTrace, options.parameters, 3, 4);
    record = nullptr;
    return buffer.meanImage();
}

} // namespace

TEST_CASE("8 threads on any machine: all render at once, and the image is the seed's",
          "[render][threads]") {
    ThreadRecord one, eight;
    const std::vector<float> single = renderWith(1, one);
    const std::vector<float> oversubscribed = renderWith(8, eight);
    INFO("this machine has " << std::thread::hardware_concurrency() << " hardware threads");
    CHECK(eight.mostInside == 8);
    REQUIRE(eight.samples.size() == 8);
    // Each thread went on with the tile its first sample was in: 16x16 pixels of 4 samples.
    for (const auto& [thread, samples] : eight.samples) CHECK(samples >= 1024);
    REQUIRE(single.size() == oversubscribed.size());
    CHECK(std::memcmp(single.data(), oversubscribed.data(), single.size() * sizeof(float)) == 0);
}
