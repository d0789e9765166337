// The checks where a lab's bugs first show (pathlab/support/check.h): a helper given a missed hit,
// a ray that is not unit length, and the report of the first non-finite sample of a render.
#include "catch.h"
#include "messages.h"
#include "test_support.h"

#include "pathlab/render/scene_from_options.h"
#include "pathlab/support/check.h"
#include "pathlab/render/path_driver.h"
#include "pathlab/render/renderer.h"
#include "pathlab/scattering.h"

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

using namespace pathlab;

namespace {

constexpr int Size = 24;
constexpr uint64_t Seed = 11;

/// Renders `spp` samples per pixel of the VI2 box at Size² with `pathTrace`, on two threads (so
/// tiles finish in no fixed order).
Renderer& renderWith(PathTraceFunction pathTrace, int spp, AccumulationBuffer& buffer) {
    static const std::string scene = test::modelPath("cornell_box_VI2_Specular.ecs");
    static const char* argv[] = {"viewer", "-c", scene.c_str()};
    static const RenderScene renderScene(loadScene(parseRenderOptions(3, argv)));
    static Renderer renderer(renderScene, 2);
    renderer.resetCounts();
    const Camera camera(*renderScene.scene().camera, Size, Size);
    renderer.renderPass(buffer, camera, pathTrace, LabParameters(), Seed, spp);
    return renderer;
}

/// Checks that `message` holds each of `parts`, a check each: a failure shows the message and
/// the part it lacks.
void checkMentions(const std::string& message, const std::vector<std::string>& parts) {
    INFO(message);
    for (const std::string& part : parts) {
        CAPTURE(part);
        CHECK(contains(message, part));
    }
}

std::string checkMessage(PathTraceFunction pathTrace) {
    AccumulationBuffer buffer(Size, Size);
    try {
        renderWith(pathTrace, 1, buffer);
    } catch (const CheckFailure& failure) {
        return failure.what();
    }
    return "no check failed";
}

// The lines of the calls a check must name: the lab's, not the framework's.
constexpr int BounceLine = __LINE__ + 2;
Color bounceOffMissedHit(const Ray&, int, PathContext& ctx) {
    return Color(diffuseRay(Hit(), ctx.sampler.get2D()).direction.x);
}
Color mirrorOffMissedHit(const Ray& ray, int, PathContext&) {
    return Color(mirrorRay(ray, Hit()).direction.x);
}
Color lightAtMissedHit(const Ray&, int, PathContext& ctx) { return ctx.directLight(Hit()); }
Color traceAndEmit(const Ray& ray, int, PathContext& ctx) { return ctx.trace(ray).emitted; }
constexpr int LongRayLine = __LINE__ + 2;
Color traceLongRay(const Ray& ray, int, PathContext& ctx) {
    return ctx.trace({ray.origin, ray.direction * 2.0f, ray.kind}).emitted;
}
constexpr float NotAWeight = std::numeric_limits<float>::quiet_NaN();
constexpr int WeightLine = __LINE__ + 3;
Color weighNaN(const Ray& ray, int, PathContext& ctx) {
    const Hit hit = ctx.trace(ray);
    return hit.emitted * ctx.strategyWeight(Strategy::Lobe, NotAWeight);
}
Color sampleLightAtMissedHit(const Ray&, int, PathContext& ctx) {
    return ctx.sampleLight(Hit()).radiance;
}

/// NaN for the samples whose first random number after the pixel jitter is below 1%, after one
/// bounce (two rays traced); the scene's radiance otherwise.
constexpr float NanFraction = 0.01f;
Color nanNowAndThen(const Ray& ray, int, PathContext& ctx) {
    const Hit hit = ctx.trace(ray);
    if (ctx.sampler.get1D() >= NanFraction) return hit.emitted;
    if (hit) ctx.trace(diffuseRay(hit, ctx.sampler.get2D()));
    return Color(std::numeric_limits<float>::quiet_NaN(), 1.0f, 0.0f);
}

} // namespace

TEST_CASE("the bounce helpers and directLight refuse a missed hit, naming themselves and the "
          "lab's line",
          "[render][checks]") {
    const std::string labLine = "checks_test.cpp:" + std::to_string(BounceLine);
    checkMentions(checkMessage(bounceOffMissedHit),
                  {labLine + ": check failed: diffuseRay(hit, u) needs a surface",
                   "scattering.cpp:", ": hit.found]"});
    checkMentions(checkMessage(mirrorOffMissedHit), {"mirrorRay(ray, hit) needs a surface"});
    checkMentions(checkMessage(lightAtMissedHit), {"ctx.directLight(hit) needs a surface"});
}

TEST_CASE("lab 6's ctx.strategyWeight refuses a weight outside [0, 1], and sampleLight a missed "
          "hit, naming the lab's line",
          "[render][checks]") {
    checkMentions(checkMessage(weighNaN),
                  {"checks_test.cpp:" + std::to_string(WeightLine) + ": check failed",
                   "ctx.strategyWeight's weight nan is not between 0 and 1",
                   "misWeight (TODO lab6.2)"});
    checkMentions(checkMessage(sampleLightAtMissedHit), {"ctx.sampleLight(hit) needs a surface"});
}

TEST_CASE("ctx.trace refuses a direction that is not unit length, naming the lab's line and "
          "the length",
          "[render][checks]") {
    checkMentions(checkMessage(traceLongRay),
                  {"checks_test.cpp:" + std::to_string(LongRayLine) + ": check failed",
                   "unit-length ray.direction, and this camera ray's has length 2.0",
                   "before the call of pathTrace that received it", "path_context.cpp:"});
}

TEST_CASE("the first non-finite sample is reported by sample index and pixel, whatever the "
          "order tiles ran in",
          "[render][checks]") {
    // The expectation, found independently of the renderer: the same random numbers, drawn as
    // the renderer draws them (the jitter's two, then the lab's first), scanned in order.
    std::optional<NonfiniteSample> expected;
    int nanPixels = 0;
    const int spp = 4;
    for (int y = 0; y < Size; ++y)
        for (int x = 0; x < Size; ++x) {
            bool pixelHasNan = false;
            for (int s = 0; s < spp; ++s) {
                Sampler sampler = PathDriver::samplerFor(Seed, static_cast<uint64_t>(y * Size + x),
                                                         static_cast<uint64_t>(s));
                sampler.get2D();
                if (sampler.get1D() >= NanFraction) continue;
                pixelHasNan = true;
                const NonfiniteSample sample{x, y, static_cast<uint64_t>(s), 0, Color()};
                if (!expected || sample.before(*expected)) expected = sample;
            }
            nanPixels += pixelHasNan;
        }
    REQUIRE(expected); // 2304 samples at 1%: none would be a 1e-10 chance

    AccumulationBuffer buffer(Size, Size);
    const Renderer& renderer = renderWith(nanNowAndThen, spp, buffer);
    REQUIRE(renderer.firstNonfinite());
    const NonfiniteSample& first = *renderer.firstNonfinite();
    CHECK(first.x == expected->x);
    CHECK(first.y == expected->y);
    CHECK(first.sampleIndex == expected->sampleIndex);
    CHECK(std::isnan(first.radiance.r));
    CHECK(first.radiance.g == 1.0f);
    CHECK(buffer.summary().nonfinitePixels == nanPixels);

    // The line the viewer prints names all of it.
    RenderStats stats =
        renderStats({{Lab::Roulette, Implementation::Student, {}, Seed}, "box"}, buffer, 2, 1.0,
                    renderer.rayCounters(), renderer.firstNonfinite());
    checkMentions(stats.nonfiniteWarning(),
                  {std::to_string(nanPixels) + " pixel(s)",
                   "pixel (" + std::to_string(expected->x) + ", " + std::to_string(expected->y) +
                       "), sample " + std::to_string(expected->sampleIndex),
                   "lab roulette (student)"});

    // And --stats keeps it, its NaN as text.
    const std::string file = test::temporaryFolder("checks") + "/stats.json";
    writeRenderStats(file, stats);
    const RenderStats read = readRenderStats(file);
    REQUIRE(read.firstNonfinite);
    CHECK(read.firstNonfinite->x == first.x);
    CHECK(read.firstNonfinite->sampleIndex == first.sampleIndex);
    CHECK(read.firstNonfinite->raysTraced == first.raysTraced);
    CHECK(std::isnan(read.firstNonfinite->radiance.r));
}

TEST_CASE("a render whose samples are all finite reports none", "[render][checks]") {
    AccumulationBuffer buffer(Size, Size);
    const Renderer& renderer = renderWith(traceAndEmit, 2, buffer);
    CHECK_FALSE(renderer.firstNonfinite());
}
