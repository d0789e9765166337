// The inspector's table and the replay's comparison on paths made by hand: the cases of lab 4 at a
// vertex where the roulette draw and the path's going on disagree for a good reason, or a bad one.
#include "catch.h"

#include "pathlab/inspect/inspection_table.h"
#include "pathlab/inspect/path_comparison.h"

#include <string>

using namespace pathlab;

namespace {

/// A lab-4 inspection of one sample: a camera hit on `material` at vertex 0, then depth 1..last
/// on a grey wall, the last vertex ending with `endDraws` random numbers drawn before the end.
PixelInspection rouletteSample(const Material& first, int vertices, std::vector<float> endDraws) {
    PixelInspection p;
    p.identity.lab = Lab::Roulette;
    p.identity.parameters = {3, 0.8f};
    p.usesRoulette = true;
    InspectedSample s;
    for (int i = 0; i < vertices; ++i) {
        InspectedVertex v;
        v.index = i, v.parent = i - 1, v.depth = i, v.found = true;
        v.arrivedBy = i == 0 ? "camera" : "diffuse";
        v.material = first;
        if (i > 0) v.material.Kd = {0.5f, 0.5f, 0.5f}, v.material.Ke = {};
        const bool last = i == vertices - 1;
        if (!last) {
            v.continuedBy.push_back({i + 1, "diffuse", 0.4f, ""});
            v.roulette = RouletteDraw{0.25f, 0.8f, true};
        } else if (!endDraws.empty()) {
            v.roulette = RouletteDraw{endDraws.front(), 0.8f, false};
        }
        s.vertices.push_back(v);
        s.calls.push_back({"trace", i, i == 0 ? std::vector<float>{} : std::vector<float>{0.25f}});
    }
    s.calls.push_back({"end", -1, endDraws});
    p.samples.push_back(s);
    return p;
}

Material light() {
    Material m;
    m.Kd = {}, m.Ke = {20, 20, 20};
    return m;
}

Material greyWall() {
    Material m;
    m.Kd = {0.5f, 0.5f, 0.5f};
    return m;
}

} // namespace

TEST_CASE("the inspector's table: a light that ends the path after a low roulette draw is not "
          "flagged, a wall is",
          "[inspector]") {
    // The reference solution draws its roulette number first, then picks a component: on a light
    // every component is black and the path ends whatever the draw said.
    const std::string onLight = inspectionTable(rouletteSample(light(), 1, {0.3f}));
    CHECK(onLight.find("(roulette 0.3 < 0.8)") != std::string::npos);
    CHECK(onLight.find("ENDED") == std::string::npos);
    const std::string onWall = inspectionTable(rouletteSample(greyWall(), 1, {0.3f}));
    CHECK(onWall.find("ENDED although the draw is below continueProb") != std::string::npos);
}

TEST_CASE("the replay: a lab 4 path that ends at maxDepth without a draw, where the reference "
          "drew its roulette number and stopped, keeps a depth limit",
          "[inspector]") {
    // Both paths end at vertex 3 (depth 3 = maxDepth): the reference after its roulette draw of
    // 0.9 (not below 0.8), the lab without drawing.
    const PixelInspection reference = rouletteSample(greyWall(), 4, {0.9f});
    const PixelInspection lab = rouletteSample(greyWall(), 4, {});
    const PathComparison atMaxDepth = comparePaths(lab, reference);
    REQUIRE(atMaxDepth.divergence);
    CHECK(atMaxDepth.divergence->kind == "depth");
    CHECK(atMaxDepth.divergence->step == "lab4.2");
    CHECK(atMaxDepth.divergence->text.find("a depth limit is still there") != std::string::npos);

    // Above maxDepth's depth it is a roulette number drawn from elsewhere.
    const PathComparison early =
        comparePaths(rouletteSample(greyWall(), 2, {}), rouletteSample(greyWall(), 2, {0.9f}));
    REQUIRE(early.divergence);
    CHECK(early.divergence->kind == "roulette");
    CHECK(early.divergence->text.find("ctx.sampler.get1D()") != std::string::npos);

    // The same draws on both sides: nothing to say.
    CHECK(!comparePaths(reference, reference).divergence);
}

TEST_CASE("the replay: a lab that bounces without drawing from ctx.sampler is told where its "
          "numbers come from; a stub that never bounces is told what it does not trace",
          "[inspector]") {
    const PixelInspection reference = rouletteSample(greyWall(), 4, {0.9f});
    PixelInspection ownNumbers = rouletteSample(greyWall(), 4, {});
    for (InspectedCall& call : ownNumbers.samples[0].calls) call.drawsBefore.clear();
    const PathComparison bouncing = comparePaths(ownNumbers, reference);
    REQUIRE(bouncing.divergence);
    CHECK(bouncing.divergence->kind == "own-random");

    // The camera ray alone, no draw: a stub, whose first difference is the bounce it lacks.
    const PathComparison stub = comparePaths(rouletteSample(greyWall(), 1, {}), reference);
    REQUIRE(stub.divergence);
    CHECK(stub.divergence->kind != "own-random");
    CHECK(stub.divergence->text.find("drew no random number") == std::string::npos);
}

TEST_CASE("the inspector's table: a roulette draw just below 1 is not shown as 1, and a ray "
          "weighted by another component's colour says so rather than a division",
          "[inspector]") {
    const std::string high = inspectionTable(rouletteSample(greyWall(), 1, {0.9996f}));
    CHECK(high.find("(roulette 0.9996 >= 0.8)") != std::string::npos);
    const std::string near = inspectionTable(rouletteSample(greyWall(), 1, {0.79999f}));
    CHECK(near.find("(roulette 0.79999 < 0.8)") != std::string::npos);

    PixelInspection weighted = rouletteSample(greyWall(), 2, {0.9f});
    weighted.samples[0].vertices[0].continuedBy[0] = {1, "mirror", 0.111f, "Kt"};
    const std::string table = inspectionTable(weighted);
    CHECK(table.find("mirror→1 weighted by Kt") != std::string::npos);
    CHECK(table.find("/0.111") == std::string::npos);
}
