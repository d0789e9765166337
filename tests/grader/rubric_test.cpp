// The rubric's speed measure per lab and its parameter check: read as written, defaults where a
// rubric from before them is silent, and a clear error for a nonsensical value.
#include "catch.h"
#include "messages.h"

#include "checks/rubric.h"

#include "pathlab/support/input_error.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace pathlab;
using namespace pathlab::grader;

namespace {

nlohmann::json kitRubric() {
    std::ifstream in(std::string(PATHLAB_GRADER_DIR) + "/rubric.json");
    return nlohmann::json::parse(in);
}

/// `rubric` written to a file of its own and read back.
Rubric load(const nlohmann::json& rubric) {
    const std::string path = (std::filesystem::temp_directory_path() /
                              ("pathlab-rubric-test-" + std::to_string(::getpid()) + ".json"))
                                 .string();
    std::ofstream(path) << rubric.dump();
    struct Remove {
        std::string path;
        ~Remove() { std::remove(path.c_str()); }
    } remove{path};
    return loadRubric(path);
}

std::string errorOf(const nlohmann::json& rubric) {
    return messageOf<InputError>([&] { load(rubric); });
}

} // namespace

TEST_CASE("the kit's rubric: speed by samples/s, parameter check at maxDepth 5 and q 0.5",
          "[grader]") {
    const Rubric r = load(kitRubric());
    for (Lab lab : AllLabs) CHECK(r.forLab(lab).speedJudgedBy == SpeedMeasure::SamplesPerSecond);
    CHECK(r.parameterCheck.scene == "furnace");
    CHECK(r.parameterCheck.maxDepth == 5);
    CHECK(r.parameterCheck.continueProb == 0.5f);
}

TEST_CASE("a rubric may judge one lab's speed by efficiency", "[grader]") {
    nlohmann::json j = kitRubric();
    j["speed"]["judged_by"]["uniform"] = "efficiency";
    const Rubric r = load(j);
    CHECK(r.forLab(Lab::Uniform).speedJudgedBy == SpeedMeasure::Efficiency);
    CHECK(r.forLab(Lab::Importance).speedJudgedBy == SpeedMeasure::SamplesPerSecond);
}

TEST_CASE("a rubric written before judged_by and parameter_check gets the defaults", "[grader]") {
    nlohmann::json j = kitRubric();
    j["speed"].erase("judged_by");
    j.erase("parameter_check");
    const Rubric r = load(j);
    CHECK(r.forLab(Lab::Roulette).speedJudgedBy == SpeedMeasure::SamplesPerSecond);
    CHECK(r.parameterCheck.maxDepth == 5);
}

TEST_CASE("nonsense in judged_by or parameter_check is named", "[grader]") {
    nlohmann::json j = kitRubric();
    j["speed"]["judged_by"]["uniform"] = "fastest";
    CHECK(contains(errorOf(j), "speed.judged_by.uniform is 'fastest'; it must be "
                               "samples_per_second or efficiency"));
    j = kitRubric();
    j["parameter_check"]["max_depth"] = j["parameters"]["max_depth"];
    CHECK(contains(errorOf(j), "parameter_check needs"));
    j = kitRubric();
    j["parameter_check"]["continue_prob"] = 1.5;
    CHECK(contains(errorOf(j), "parameter_check needs"));
}
