// The path inspector on the furnace (a closed sphere of diffuse albedo a = 0.5 emitting Le = 1),
// through the reference solutions, against values worked out by hand. Every surface is the
// same diffuse wall, so each lab's weights follow from its estimator alone:
//   branching and importance: a bounce's weight is Kd (the pick has probability 1), so the
//     throughput at depth k is a^k;
//   uniform: the diffuse component is picked with probability 1/3 and divided by it: (3a)^k;
//   roulette at continueProb p: (a/p)^k, and the probability divided by is 1 · p.
// Emission is added at the camera ray's hit only (weight 1), never after a diffuse bounce; the
// sample's value is then Le + Σ_k throughput_k · directLight_k, which the test checks too: the
// measured weights must account for the whole value. No randomness is compared with a
// tolerance: the replay is exact, and the tolerances below are float rounding.
#include "catch.h"
#include "test_support.h"

#include "runner/pixel_replay.h"

#include "pathlab/render/scene_from_options.h"
#include "pathlab/inspect/inspection_json.h"
#include "pathlab/render/render_scene.h"
#include "pathlab/support/input_error.h"

#include <cmath>
#include <string>
#include <vector>

using namespace pathlab;
using namespace pathlab::test;

namespace {

constexpr float Albedo = 0.5f;

RenderOptions furnaceOptions(const std::string& lab, std::vector<std::string> extra = {}) {
    std::vector<std::string> arguments = {"viewer",
                                          "-c",
                                          modelPath("furnace.ecs"),
                                          "--lab",
                                          lab,
                                          "--solution",
                                          "--size",
                                          "32",
                                          "32",
                                          "--inspect",
                                          "16",
                                          "16",
                                          "--inspect-samples",
                                          "8"};
    arguments.insert(arguments.end(), extra.begin(), extra.end());
    std::vector<const char*> argv;
    for (const std::string& a : arguments) argv.push_back(a.c_str());
    return parseRenderOptions(static_cast<int>(argv.size()), argv.data());
}

PixelInspection inspectFurnace(const std::string& lab, std::vector<std::string> extra = {}) {
    const RenderOptions options = furnaceOptions(lab, extra);
    const RenderScene scene(loadScene(options));
    return replayPixel(options, scene).lab;
}

void checkGrey(const Color& c, double expected) {
    CHECK(c.r == Approx(expected).epsilon(1e-4).margin(1e-6));
    CHECK(c.g == Approx(expected).epsilon(1e-4).margin(1e-6));
    CHECK(c.b == Approx(expected).epsilon(1e-4).margin(1e-6));
}

/// Checks every vertex of every sample against the lab's weight per bounce and probability.
void checkFurnacePaths(const PixelInspection& inspection, double weightPerBounce,
                       double probability) {
    REQUIRE(inspection.samples.size() == 8);
    size_t bounces = 0;
    for (const InspectedSample& sample : inspection.samples) {
        REQUIRE(!sample.vertices.empty());
        Color sum{1, 1, 1}; // Le at the camera ray's hit
        for (const InspectedVertex& v : sample.vertices) {
            REQUIRE(v.found); // the furnace is closed
            CHECK(v.arrivedBy == (v.index == 0 ? "camera" : "diffuse"));
            CHECK(v.depth == v.index);
            CHECK(v.parent == v.index - 1);
            REQUIRE(v.throughput);
            checkGrey(*v.throughput, std::pow(weightPerBounce, v.depth));
            REQUIRE(v.emissionWeight);
            checkGrey(*v.emissionWeight, v.index == 0 ? 1.0 : 0.0);
            CHECK(v.directLightCalled);
            CHECK(v.shadowRay);
            sum += v.directLightAdded;
            REQUIRE(v.continuedBy.size() <= 1);
            for (const PathContinuation& c : v.continuedBy) {
                CHECK(c.component == "diffuse");
                REQUIRE(c.probability);
                CHECK(*c.probability == Approx(probability).epsilon(1e-4));
                ++bounces;
            }
        }
        checkGrey(sample.contribution, sum.r);
    }
    CHECK(bounces > 0);
}

} // namespace

TEST_CASE("inspector: branching's throughput is Kd^k, depth limited", "[solutions]") {
    const PixelInspection inspection = inspectFurnace("branching");
    checkFurnacePaths(inspection, Albedo, 1.0);
    for (const InspectedSample& sample : inspection.samples) {
        CHECK(sample.vertices.size() == 4); // depths 0..maxDepth 3, every one bouncing but the last
        CHECK(sample.vertices.back().continuedBy.empty());
    }
}

TEST_CASE("inspector: uniform divides by 1/3", "[solutions]") {
    checkFurnacePaths(inspectFurnace("uniform"), 3 * Albedo, 1.0 / 3.0);
}

TEST_CASE("inspector: importance's pick has probability 1 on a diffuse wall", "[solutions]") {
    checkFurnacePaths(inspectFurnace("importance"), Albedo, 1.0);
}

TEST_CASE("inspector: roulette divides by continueProb and records its draw", "[solutions]") {
    const float p = 0.8f;
    const PixelInspection inspection = inspectFurnace("roulette", {"--continue-prob", "0.8"});
    checkFurnacePaths(inspection, Albedo / p, p);
    for (const InspectedSample& sample : inspection.samples)
        for (const InspectedVertex& v : sample.vertices) {
            REQUIRE(v.roulette);
            CHECK(v.roulette->wentOn == (v.roulette->draw < p));
            CHECK(v.roulette->wentOn == !v.continuedBy.empty());
            // The roulette draw alone when the path ends; with the pick and the direction's two
            // when it goes on.
            CHECK(v.draws.size() == (v.roulette->wentOn ? 4u : 1u));
        }
}

TEST_CASE("inspector: the JSON reads back as written", "[solutions]") {
    const PixelInspection written = inspectFurnace("roulette", {"--continue-prob", "0.8"});
    const PixelInspection read = readInspectionJson(inspectionJson(written), "test");
    REQUIRE(read.samples.size() == written.samples.size());
    CHECK(read.identity.lab == Lab::Roulette);
    CHECK(read.identity.implementation == written.identity.implementation);
    CHECK(read.identity.seed == written.identity.seed);
    CHECK(read.identity.parameters.maxDepth == written.identity.parameters.maxDepth);
    CHECK(read.identity.parameters.continueProb == written.identity.parameters.continueProb);
    CHECK(read.usesRoulette);
    for (size_t s = 0; s < read.samples.size(); ++s) {
        const auto& a = written.samples[s];
        const auto& b = read.samples[s];
        REQUIRE(a.vertices.size() == b.vertices.size());
        CHECK(a.calls.size() == b.calls.size());
        for (size_t v = 0; v < a.vertices.size(); ++v) {
            CHECK(b.vertices[v].throughput->r == a.vertices[v].throughput->r);
            CHECK(b.vertices[v].draws == a.vertices[v].draws);
        }
    }
    // Compared with itself, a lab's paths agree everywhere.
    const PathComparison same = comparePaths(read, written);
    CHECK(same.comparable);
    CHECK(!same.divergence);
    CHECK(same.samplesCompared == 8);
}

TEST_CASE("inspector: the replay is the render's sample", "[solutions]") {
    // The replay draws the pixel's random numbers as a render does: the mean of its samples'
    // values is the rendered pixel's mean at the same spp (the camera ray traced alone and in a
    // packet may differ in the last bits).
    const RenderOptions options = furnaceOptions("uniform");
    const RenderScene scene(loadScene(options));
    const PixelInspection inspection = replayPixel(options, scene).lab;
    const HeadlessResult rendered = render({"-c", modelPath("furnace.ecs"), "--lab", "uniform",
                                            "--solution", "--size", "32", "32", "--spp", "8"});
    Color mean;
    for (const InspectedSample& sample : inspection.samples) mean += sample.contribution * 0.125f;
    const std::vector<float> image = rendered.image.meanImage();
    CHECK(mean.r == Approx(image[3 * (16 * 32 + 16)]).epsilon(1e-4));
}

TEST_CASE("inspector: a JSON naming no lab of the kit is refused by name", "[solutions]") {
    std::string text = inspectionJson(inspectFurnace("branching"));
    text.replace(text.find("\"branching\""), 11, "\"velvet\"");
    std::string message;
    try {
        readInspectionJson(text, "replay.json");
    } catch (const InputError& error) {
        message = error.what();
    }
    CHECK(message.find("replay.json: the lab \"velvet\" is none of this kit's") == 0);
}
