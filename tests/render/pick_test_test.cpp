// The pick test (pathlab/inspect/pick_test.h) on made-up replays whose frequencies are known:
// picks that follow what the lab divides by pass, picks that do not fail with the material and
// the two numbers, a branching lab and total internal reflection are read as the header says.
#include "catch.h"

#include "pathlab/inspect/pick_test.h"

#include <string>

using namespace pathlab;

namespace {

Material mirrorAndGlass() {
    Material m;
    m.Ks = Color(0.1f);
    m.Kt = Color(0.9f);
    return m;
}

/// A lab-3 replay of `visits` vertices on `m`: the first `refractions` go on by refraction and
/// the rest by the mirror, each divided by `divideRefraction` or `divideMirror`.
PixelInspection visits(const Material& m, int count, int refractions, float divideRefraction,
                       float divideMirror) {
    PixelInspection inspection;
    inspection.identity.lab = Lab::Importance;
    inspection.identity.parameters = {3, 0.8f};
    InspectedSample sample;
    for (int i = 0; i < count; ++i) {
        InspectedVertex v;
        v.found = true;
        v.depth = 0;
        v.material = m;
        const bool refracted = i < refractions;
        v.continuedBy.push_back({1, refracted ? "refraction" : "mirror",
                                 refracted ? divideRefraction : divideMirror, ""});
        sample.vertices.push_back(v);
    }
    inspection.samples.push_back(sample);
    return inspection;
}

} // namespace

TEST_CASE("pick test: picks at the frequencies divided by pass", "[inspect][pick]") {
    const PickTestResult result = testPicks({visits(mirrorAndGlass(), 1000, 900, 0.9f, 0.1f)});
    INFO(describePickTest(result));
    REQUIRE(result.applies);
    CHECK(result.passed);
    REQUIRE(result.materials.size() == 1);
    CHECK(result.materials[0].visits == 1000);
    CHECK(result.materials[0].claimedTotal == Approx(1));
}

TEST_CASE("pick test: picks at 0.33 divided by 0.9 fail, named", "[inspect][pick]") {
    const PickTestResult result = testPicks({visits(mirrorAndGlass(), 1000, 333, 0.9f, 0.1f)});
    CHECK_FALSE(result.passed);
    REQUIRE(result.problems.size() == 1);
    CHECK(result.problems[0] == "at Ks 0.1 Kt 0.9 (1000 visits) you went on by mirror with "
                                "frequency 0.667 and divided by 0.1");
    CHECK(describePickTest(result).find("FAILED") != std::string::npos);
}

TEST_CASE("pick test: divisions that add up to more than 1 fail", "[inspect][pick]") {
    const PickTestResult result = testPicks({visits(mirrorAndGlass(), 1000, 500, 0.9f, 0.5f)});
    CHECK_FALSE(result.passed);
    REQUIRE_FALSE(result.problems.empty());
    CHECK(result.problems[0].find("add up to 1.4, more than 1") != std::string::npos);
}

TEST_CASE("pick test: a branching lab and rare materials are not tested", "[inspect][pick]") {
    PixelInspection branching = visits(mirrorAndGlass(), 200, 100, 1, 1);
    branching.samples[0].vertices[0].continuedBy.push_back({2, "mirror", 1.0f, ""});
    CHECK_FALSE(testPicks({branching}).applies);
    CHECK_FALSE(testPicks({visits(mirrorAndGlass(), 50, 45, 0.9f, 0.1f)}).applies);
    CHECK(describePickTest(testPicks({})).find("nothing to test") != std::string::npos);
}

TEST_CASE("pick test: total internal reflection is the pick of the one specular component",
          "[inspect][pick]") {
    // Glass without a mirror component: a specular ray is a refraction pick.
    Material glass;
    glass.Kd = Color(0.5f);
    glass.Kt = Color(0.5f);
    PixelInspection inspection = visits(glass, 1000, 400, 0.5f, 0.5f);
    for (size_t i = 400; i < 1000; ++i) {
        PathContinuation& c = inspection.samples[0].vertices[i].continuedBy[0];
        c.component = i < 500 ? "specular" : "diffuse"; // 100 total reflections
    }
    const PickTestResult result = testPicks({inspection});
    INFO(describePickTest(result));
    REQUIRE(result.applies);
    CHECK(result.passed);
    bool refraction500 = false;
    for (const ComponentPicks& c : result.materials[0].components)
        refraction500 = refraction500 || (c.component == "refraction" && c.picked == 500);
    CHECK(refraction500);
}
