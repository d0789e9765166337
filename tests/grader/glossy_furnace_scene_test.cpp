// The glossy furnaces as the grader grades lab 5 on them
// (grader/src/checks/glossy_furnace_scene.h): their analytic values against an independent reading
// of the scenes' files, for lab 5 alone, and the tilted one's variant per submission: another
// exponent and angle for another seed, the same for the same seed, its value the lobe's reflectance
// at them.
#include "catch.h"
#include "test_support.h"

#include "checks/glossy_furnace_scene.h"
#include "checks/rubric.h"

#include "pathlab/warp/phong_albedo.h"
#include "pathlab/support/whole_file.h"

#include <cmath>
#include <sstream>

using namespace pathlab;
using namespace pathlab::grader;

namespace {

Rubric kitRubric() { return loadRubric(std::string(PATHLAB_GRADER_DIR) + "/rubric.json"); }

constexpr double Pi = 3.14159265358979323846;

/// The value a variant's files say, read here from the text: Ks 0.8 times the lobe's
/// reflectance at the material's Ns and the camera's angle from the plate's normal (-z).
double variantValue(const std::string& folder) {
    std::istringstream mtl(readFile(folder + "/glossy_furnace.mtl"));
    std::istringstream ecs(readFile(folder + "/glossy_furnace_tilted.ecs"));
    double ns = 0, y = 0, z = 0;
    for (std::string word; mtl >> word;)
        if (word == "Ns") mtl >> ns;
    for (std::string word; ecs >> word;)
        if (word == "-vp") ecs >> word >> y >> z;
    return 0.8 * phongGlowReflectance(ns, std::atan2(y, -z));
}

} // namespace

TEST_CASE("the glossy furnaces grade lab 5 alone, at Ks head-on and Ks times the lobe's "
          "reflectance at 60 degrees",
          "[grader]") {
    const std::vector<GradingScene> scenes = glossyFurnaceScenes(kitRubric());
    REQUIRE(scenes.size() == 2);
    for (const GradingScene& scene : scenes) {
        CHECK(scene.grades(Lab::Glossy));
        for (Lab lab : {Lab::Branching, Lab::Uniform, Lab::Importance, Lab::Roulette})
            CHECK_FALSE(scene.grades(lab));
    }
    CHECK(scenes[0].reference.unbiased.mean.front() == Approx(0.8).epsilon(1e-6));
    CHECK(scenes[1].reference.unbiased.mean.front() ==
          Approx(0.8 * phongGlowReflectance(12, 60 * Pi / 180)).epsilon(1e-5));
    CHECK(scenes[1].reference.unbiased.mean.front() == Approx(0.4023).epsilon(1e-3));
}

TEST_CASE("the tilted glossy furnace's variant: drawn from the submission's seed, its value "
          "from its own files",
          "[grader]") {
    const Rubric rubric = kitRubric();
    const std::string one = test::temporaryFolder("glossy-variant-1");
    const std::string two = test::temporaryFolder("glossy-variant-2");
    const GradingScene a = tiltedGlossyFurnaceVariant(rubric, 7, one);
    const GradingScene again = tiltedGlossyFurnaceVariant(rubric, 7, two);
    const double valueA = a.reference.unbiased.mean.front();
    CHECK(valueA == again.reference.unbiased.mean.front());
    CHECK(valueA == Approx(variantValue(one + "/glossy_furnace_variant")).epsilon(1e-5));
    CHECK(a.name == "glossy_furnace_tilted");
    CHECK(a.grades(Lab::Glossy));
    CHECK_FALSE(a.grades(Lab::Roulette));
    const GradingScene b = tiltedGlossyFurnaceVariant(rubric, 8, two);
    CHECK(b.reference.unbiased.mean.front() != valueA);
    CHECK(b.reference.unbiased.mean.front() ==
          Approx(variantValue(two + "/glossy_furnace_variant")).epsilon(1e-5));
}
