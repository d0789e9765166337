// Hidden scenes in Gradescope's results: a test of their own per lab, no points of its own, with
// the rubric's visibility; the lab's visible tests and the submission's output leave them out.
// PrairieLearn's results, which can show a test only to all or none, leave them out altogether.
#include "catch.h"

#include "checks/correctness_check.h"
#include "checks/rubric.h"
#include "reports/reports.h"

#include "pathlab/support/input_error.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace pathlab;
using namespace pathlab::grader;

namespace {

GradeReport reportWithHiddenScene() {
    LabGrade lab;
    lab.lab = Lab::Uniform;
    CheckResult correctness;
    correctness.kind = CheckKind::Correctness;
    correctness.maxScore = 6;
    correctness.summary = "mean radiance differs from the depth-limited image";
    correctness.details = {"furnace: observed/expected red 0.826"};
    correctness.hiddenSceneDetails = {"hidden scene 1: differs from its reference",
                                      "hidden scene 2: matches its reference"};
    lab.checks = {correctness};
    GradeReport report;
    report.labs = {lab};
    return report;
}

std::string visibilityError(const std::string& visibility) {
    std::ifstream in(std::string(PATHLAB_GRADER_DIR) + "/rubric.json");
    nlohmann::json j = nlohmann::json::parse(in);
    j["hidden_scenes"]["gradescope_visibility"] = visibility;
    const std::string path = (std::filesystem::temp_directory_path() /
                              ("pathlab-hidden-" + std::to_string(::getpid()) + ".json"))
                                 .string();
    std::ofstream(path) << j.dump();
    std::string error;
    try {
        loadRubric(path);
    } catch (const InputError& e) {
        error = e.what();
    }
    std::remove(path.c_str());
    return error;
}

} // namespace

TEST_CASE(
    "Gradescope: the hidden scenes' verdicts in a test of their own, shown when the rubric says",
    "[grader]") {
    const nlohmann::json results =
        nlohmann::json::parse(gradescopeReport(reportWithHiddenScene(), "after_published"));
    const auto& tests = results.at("tests");
    REQUIRE(tests.size() == 2);
    CHECK(tests[0].at("name") == "uniform: correctness");
    CHECK(tests[0].at("visibility") == "visible");
    const std::string visibleOutput = tests[0].at("output");
    CHECK(visibleOutput.find("furnace: observed/expected") != std::string::npos);
    CHECK(visibleOutput.find("differs from its reference") == std::string::npos);
    CHECK(tests[1].at("name") == "uniform: hidden scenes");
    CHECK(tests[1].at("visibility") == "after_published");
    CHECK(tests[1].at("max_score") == 0);
    CHECK(tests[1].at("status") == "failed");
    CHECK(tests[1].at("output") ==
          "hidden scene 1: differs from its reference\nhidden scene 2: matches its reference");
    const std::string output = results.at("output");
    CHECK(output.find("hidden scene 1") == std::string::npos);

    // The student's own feedback (terminal, JSON) says pass or fail per hidden scene, by number.
    CHECK(terminalReport(reportWithHiddenScene(), false).find("hidden scene 1: differs") !=
          std::string::npos);
}

TEST_CASE("PrairieLearn: a test per lab and check, the score a fraction, no hidden scene named",
          "[grader]") {
    GradeReport report = reportWithHiddenScene();
    CheckResult noise;
    noise.kind = CheckKind::Noise;
    noise.maxScore = 2;
    noise.score = 2;
    noise.passed = true;
    noise.summary = "noise 1.02 times the reference's";
    report.labs[0].checks.push_back(noise);
    const nlohmann::json results = nlohmann::json::parse(prairieLearnReport(report));
    CHECK(results.at("gradable") == true);
    CHECK(results.at("score").get<double>() == Approx(0.25)); // 2 of 8 points
    const auto& tests = results.at("tests");
    REQUIRE(tests.size() == 2);
    CHECK(tests[0].at("name") == "uniform: correctness");
    CHECK(tests[0].at("points") == 0);
    CHECK(tests[0].at("max_points") == 6);
    CHECK(tests[0].at("message") == "failed");
    CHECK(tests[1].at("name") == "uniform: noise");
    CHECK(tests[1].at("points") == 2);
    CHECK(tests[1].at("message") == "passed");
    CHECK(std::string(tests[0].at("output")).find("furnace: observed/expected") !=
          std::string::npos);
    INFO(results.dump(1));
    CHECK(results.dump().find("hidden scene") == std::string::npos);
}

TEST_CASE("the rubric's visibility of hidden scenes: one of Gradescope's four", "[grader]") {
    CHECK(visibilityError("after_published").empty());
    CHECK(visibilityError("hidden").empty());
    CHECK(visibilityError("sometimes").find("hidden_scenes.gradescope_visibility is 'sometimes'") !=
          std::string::npos);
}

TEST_CASE("a render's failure on a hidden scene shows nothing the lab printed there", "[grader]") {
    GradingScene scene;
    scene.path = "/course/hidden/secret_lantern.ecs";
    scene.reference.scene = "secret_lantern";
    scene.name = "hidden scene 2";
    scene.hidden = true;
    // What a lab prints on a hidden scene may be the scene itself, spelt any way it likes.
    const std::string failure = "crashed (Aborted, signal 6): aborted; it printed: newmtl glass\n"
                                "Ke 20 14 8\nnretnal_terces";
    const std::string shown = failureAsShown(failure, "crashed", scene);
    CHECK(shown == "crashed (on a hidden scene, what the lab printed is not shown)");
    for (const char* secret : {"newmtl", "Ke 20", "nretnal", "secret_lantern", "signal 6"})
        CHECK(shown.find(secret) == std::string::npos);
    // A kind of failure the grader does not know is not quoted either.
    CHECK(failureAsShown(failure, "Ke 20 14 8", scene) ==
          "failed (on a hidden scene, what the lab printed is not shown)");
    scene.hidden = false; // a public scene's, or one the instructor reveals: as it is
    CHECK(failureAsShown(failure, "crashed", scene) == failure);
}
