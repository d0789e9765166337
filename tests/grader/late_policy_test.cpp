// The rubric's late policy (checks/late_policy.h): days late rounded up, slip days, the penalty and
// its cap, extensions; its words for a wrong setting; and the gradebook's and the LMS's totals.
#include "catch.h"
#include "test_support.h"

#include "checks/late_policy.h"
#include "checks/rubric.h"
#include "reports/gradebook.h"
#include "reports/submission_time.h"

#include "pathlab/support/input_error.h"
#include "pathlab/support/whole_file.h"

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace pathlab;
using namespace pathlab::grader;
namespace fs = std::filesystem;

namespace {

constexpr long long kHour = 3600, kDay = 24 * kHour;

std::string errorOf(const nlohmann::json& section, const std::string& rubric) {
    try {
        readLatePolicy(section, rubric);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST_CASE("late days round up; slip days go first; the penalty per day stops at its cap",
          "[grader]") {
    LatePolicy policy;
    policy.given = true;
    policy.penaltyPerDay = 0.1;
    policy.maxPenalty = 0.25;
    policy.slipDays = 1;
    policy.extensionDays = {{"erin", 2}};
    const long long due = 1'800'000'000;
    CHECK(latenessOf(policy, "a", due, due).daysLate == 0); // on the minute: on time
    const Lateness hour = latenessOf(policy, "a", due + kHour, due);
    CHECK(hour.daysLate == 1);
    CHECK(hour.slipDaysUsed == 1);
    CHECK(hour.penalty == 0);
    const Lateness twoDays = latenessOf(policy, "a", due + kDay + kHour, due);
    CHECK(twoDays.daysLate == 2);
    CHECK(twoDays.penalty == Approx(0.1));
    CHECK(latenessOf(policy, "a", due + 9 * kDay, due).penalty == Approx(0.25)); // the cap
    CHECK(latenessOf(policy, "erin", due + kDay + kHour, due).daysLate == 0);    // extended 2 days
    CHECK(latenessOf(policy, "erin", due + 2 * kDay + kHour, due).daysLate == 1);
}

TEST_CASE("the late policy's settings and its extensions file are checked, named when wrong",
          "[grader]") {
    const test::ScratchFolder scratch("late");
    const std::string rubric = (scratch.path / "rubric.json").string();
    std::ofstream(scratch.path / "extensions.csv") << "id,days\nerin,3\nfrank,2\n";
    const LatePolicy policy =
        readLatePolicy({{"penalty_per_day", 0.1}, {"extensions", "extensions.csv"}}, rubric);
    CHECK(policy.given);
    CHECK(policy.extensionDays == std::map<std::string, int>{{"erin", 3}, {"frank", 2}});
    CHECK(latePolicyFromJson(latePolicyJson(policy)).extensionDays == policy.extensionDays);
    std::ofstream(scratch.path / "extensions.csv") << "id,days\nerin,three\n";
    CHECK(errorOf({{"extensions", "extensions.csv"}}, rubric)
              .find("extensions.csv:2: expected "
                    "id,days") != std::string::npos);
    CHECK(errorOf({{"extensions", "missing.csv"}}, rubric).find("missing.csv: cannot open") !=
          std::string::npos);
    CHECK(errorOf({{"penalty_per_day", 10}}, rubric).find("between 0 and 1") != std::string::npos);

    // In the rubric, outside its hash: a policy changed grades and re-scores nobody.
    nlohmann::json kit = nlohmann::json::parse(readFile(PATHLAB_GRADER_DIR "/rubric.json"));
    std::ofstream(rubric) << kit.dump();
    const std::string plain = loadRubric(rubric).hash;
    kit["late"] = {{"penalty_per_day", 0.1}, {"slip_days", 2}};
    std::ofstream(rubric) << kit.dump();
    const Rubric withPolicy = loadRubric(rubric);
    CHECK(withPolicy.hash == plain);
    CHECK(withPolicy.late.slipDays == 2);
}

TEST_CASE("the gradebook shows the raw total, the late days and slip days used, the penalty and "
          "the final total, which the LMS gets",
          "[grader]") {
    const test::ScratchFolder scratch("late");
    GradingNow now;
    now.rubricHash = "rubric";
    now.scenesHash = "scenes";
    now.maxScore = 40;
    now.deadline = parseTime("2026-12-01T23:59Z");
    now.late.given = true;
    now.late.penaltyPerDay = 0.1;
    now.late.slipDays = 1;
    auto result = [](const std::string& submitted) {
        return nlohmann::json{
            {"status", "graded"},
            {"score", 40},
            {"max_score", 40},
            {"graded_under", {{"rubric_hash", "rubric"}, {"scenes_hash", "scenes"}}},
            {"intake", {{"submitted_at", *parseTime(submitted)}, {"time_source", "t"}}}};
    };
    const std::vector<GradebookEntry> entries = {
        {"ann", "", result("2026-12-01T20:00Z"), "", false, std::nullopt}, // on time
        {"bo", "", result("2026-12-02T20:00Z"), "", false, std::nullopt},  // 1 day: a slip day
        {"cy", "", result("2026-12-04T20:00Z"), "", false, std::nullopt}}; // 3 days: 2 penalised
    writeGradebook(scratch.path.string(), entries, now, std::nullopt);
    const std::string csv = readFile((scratch.path / "gradebook.csv").string());
    INFO(csv);
    CHECK(csv.find(",graded_total,late_days,slip_days_used,late_penalty,final_total\n") !=
          std::string::npos);
    CHECK(csv.find(",40,0,0,0,40\n") != std::string::npos);
    CHECK(csv.find(",40,1,1,0,40\n") != std::string::npos);
    CHECK(csv.find(",40,3,1,0.2,32\n") != std::string::npos);
    const std::string lms = readFile((scratch.path / "lms.csv").string());
    CHECK(lms.find("cy,cy,32\n") != std::string::npos);
    CHECK(lms.find("bo,bo,40\n") != std::string::npos);
}
