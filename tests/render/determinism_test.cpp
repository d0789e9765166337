// The image depends on the seed alone: not on the thread count, not on the order tiles run in.
#include "catch.h"
#include "test_support.h"

#include "runner/lab_tables.h"

#include "pathlab/render/scene_from_options.h"
#include "pathlab/render/renderer.h"

#include <cstring>

using namespace pathlab;

namespace {
std::vector<float> renderVI2(const std::string& threads, const std::string& seed,
                             const std::string& lab = "importance",
                             std::vector<std::string> more = {}) {
    std::vector<std::string> arguments = {
        "-c",        test::modelPath("cornell_box_VI2_Specular.ecs"),
        "--size",    "48",
        "40",        "--spp",
        "3",         "--lab",
        lab,         "--solution",
        "--threads", threads,
        "--seed",    seed};
    arguments.insert(arguments.end(), more.begin(), more.end());
    return test::render(arguments).image.meanImage();
}
} // namespace

TEST_CASE("same seed: bit-identical images with 1 and 2 threads", "[render][rng][solutions]") {
    for (const char* lab : {"branching", "roulette"}) {
        const std::vector<float> one = renderVI2("1", "5", lab);
        const std::vector<float> two = renderVI2("2", "5", lab);
        REQUIRE(one.size() == two.size());
        CHECK(std::memcmp(one.data(), two.data(), one.size() * sizeof(float)) == 0);
    }
}

TEST_CASE("same seed: bit-identical images with the tiles in reverse order",
          "[render][rng][solutions]") {
    // The grader's reproducibility check renders a lab's tiles last to first: a lab that takes
    // its random numbers from ctx.sampler alone, as every solution does, must not see it.
    for (const char* lab : {"uniform", "roulette"}) {
        const std::vector<float> inOrder = renderVI2("1", "5", lab);
        const std::vector<float> reversed = renderVI2("1", "5", lab, {"--reverse-tiles"});
        const std::vector<float> reversedOnTwo = renderVI2("2", "5", lab, {"--reverse-tiles"});
        REQUIRE(inOrder.size() == reversed.size());
        CHECK(std::memcmp(inOrder.data(), reversed.data(), inOrder.size() * sizeof(float)) == 0);
        CHECK(std::memcmp(inOrder.data(), reversedOnTwo.data(), inOrder.size() * sizeof(float)) ==
              0);
    }
}

TEST_CASE("different seeds: different images", "[render][rng][solutions]") {
    const std::vector<float> a = renderVI2("2", "1");
    const std::vector<float> b = renderVI2("2", "2");
    size_t lit = 0, differing = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        if (a[i] == 0 && b[i] == 0) continue; // black in both: the open front, seen in the mirror
        ++lit;
        differing += a[i] != b[i];
    }
    CHECK(lit > a.size() / 2);
    CHECK(differing > lit * 99 / 100);
}

TEST_CASE("a second pass continues the sample sequence instead of repeating it",
          "[render][rng][solutions]") {
    // 2 passes of 2 spp must equal 1 pass of 4 spp: sample indices carry on across passes.
    const RenderOptions options = [] {
        const std::string scene = test::modelPath("furnace.ecs");
        const char* argv[] = {"viewer", "-c",    scene.c_str(), "--size",    "16",
                              "16",     "--lab", "uniform",     "--solution"};
        return parseRenderOptions(9, argv);
    }();
    const RenderScene scene(loadScene(options));
    const Camera camera(*scene.scene().camera, 16, 16);
    Renderer renderer(scene, 2);
    const PathTraceFunction f = findPathTrace(Lab::Uniform, Implementation::Solution);
    AccumulationBuffer twice(16, 16), once(16, 16);
    renderer.renderPass(twice, camera, f, options.parameters, 9, 2);
    renderer.renderPass(twice, camera, f, options.parameters, 9, 2);
    renderer.renderPass(once, camera, f, options.parameters, 9, 4);
    const auto a = twice.meanImage(), b = once.meanImage();
    CHECK(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0);
}
