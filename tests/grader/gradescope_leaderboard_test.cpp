// Gradescope's leaderboard (the rubric's gradescope.leaderboard): results.json's "leaderboard"
// holds the total and each lab's efficiency over the reference's, 0 for a lab that is not
// correct; without the setting there is none; a wrong setting is named; it is not graded (the
// rubric's hash does not see it).
#include "catch.h"
#include "test_support.h"

#include "checks/rubric.h"
#include "reports/reports.h"

#include "pathlab/support/input_error.h"
#include "pathlab/support/whole_file.h"

#include <nlohmann/json.hpp>

using namespace pathlab;
using namespace pathlab::grader;
using pathlab::test::ScratchFolder;

namespace {

LabGrade labGrade(Lab lab, bool correct, double efficiencyRatio) {
    LabGrade grade;
    grade.lab = lab;
    CheckResult correctness;
    correctness.kind = CheckKind::Correctness;
    correctness.maxScore = 6;
    correctness.score = correct ? 6 : 0;
    correctness.passed = correct;
    correctness.gradedHere = true;
    grade.checks.push_back(correctness);
    grade.efficiencyRatio = efficiencyRatio;
    return grade;
}

std::string rubricWith(const ScratchFolder& folder, const nlohmann::json& gradescope) {
    nlohmann::json j =
        nlohmann::json::parse(readFile(std::string(PATHLAB_GRADER_DIR) + "/rubric.json"));
    if (!gradescope.is_null()) j["gradescope"] = gradescope;
    const std::string path = (folder.path / "rubric.json").string();
    writeFileAtomically(path, j.dump(1));
    return path;
}

} // namespace

TEST_CASE("Gradescope's leaderboard: the total and each correct lab's efficiency", "[grader]") {
    GradeReport report;
    report.labs = {labGrade(Lab::Branching, true, 1.23456), labGrade(Lab::Uniform, false, 3.0)};
    const nlohmann::json with = nlohmann::json::parse(gradescopeReport(report, "visible", true));
    REQUIRE(with.contains("leaderboard"));
    const nlohmann::json& board = with.at("leaderboard");
    REQUIRE(board.size() == 3);
    CHECK(board[0] == nlohmann::json({{"name", "total"}, {"value", 6.0}}));
    CHECK(board[1].at("name") == "branching: efficiency / reference");
    CHECK(board[1].at("value").get<double>() == Approx(1.235));
    // A wrong lab's figures mean nothing: it ranks last, whatever it measured.
    CHECK(board[2].at("value").get<double>() == 0);
    const nlohmann::json without = nlohmann::json::parse(gradescopeReport(report, "visible"));
    CHECK_FALSE(without.contains("leaderboard"));
}

TEST_CASE("the rubric's gradescope.leaderboard: read, named when wrong, outside the hash",
          "[grader]") {
    ScratchFolder folder("leaderboard-rubric");
    const Rubric plain = loadRubric(rubricWith(folder, nullptr));
    CHECK_FALSE(plain.gradescopeLeaderboard);
    const Rubric on = loadRubric(rubricWith(folder, {{"leaderboard", true}}));
    CHECK(on.gradescopeLeaderboard);
    CHECK(on.hash == plain.hash);
    try {
        loadRubric(rubricWith(folder, {{"leaderboard", "yes"}}));
        FAIL("a leaderboard of \"yes\" was taken");
    } catch (const InputError& e) {
        CHECK(std::string(e.what()).find("gradescope.leaderboard must be true or false") !=
              std::string::npos);
    }
}
