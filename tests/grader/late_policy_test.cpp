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

/// The grading now, out of 40, under a policy of 10% a late day after one slip day.
GradingNow gradingWithPolicy() {
    GradingNow now;
    now.rubricHash = "rubric";
    now.scenesHash = "scenes";
    now.maxScore = 40;
    now.late.given = true;
    now.late.penaltyPerDay = 0.1;
    now.late.slipDays = 1;
    return now;
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
    GradingNow now = gradingWithPolicy();
    now.deadline = parseTime("2026-12-01T23:59Z");
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
    CHECK(csv.find(",graded_total,late_days,slip_days_used,late_penalty,final_total,late_labs\n") !=
          std::string::npos);
    CHECK(csv.find(",40,0,0,0,40,\n") != std::string::npos);
    CHECK(csv.find(",40,1,1,0,40,\n") != std::string::npos);
    CHECK(csv.find(",40,3,1,0.2,32,\n") != std::string::npos);
    const std::string lms = readFile((scratch.path / "lms.csv").string());
    CHECK(lms.find("cy,cy,32\n") != std::string::npos);
    CHECK(lms.find("bo,bo,40\n") != std::string::npos);
}

TEST_CASE("a deadline per lab: each lab late by its own time, the slip days one budget spent in "
          "the order the labs were due, a lab's own extension",
          "[grader]") {
    const long long week = 7 * kDay, first = 1'800'000'000;
    LatePolicy policy;
    policy.given = true;
    policy.penaltyPerDay = 0.1;
    policy.slipDays = 2;
    policy.labDeadlines = {
        {"branching", first}, {"uniform", first + week}, {"roulette", first + 3 * week}};
    policy.labExtensionDays = {{"erin", {{"uniform", 3}}}};
    // branching 1 day late, uniform 3 days, roulette on time, importance (no deadline of its
    // own, none for the batch) never late, glossy not handed in.
    const std::map<std::string, long long> times = {{"branching", first + kHour},
                                                    {"uniform", first + week + 2 * kDay + kHour},
                                                    {"importance", first + 9 * week},
                                                    {"roulette", first + 3 * week - kHour}};
    const std::vector<LabLateness> labs = labLatenessOf(policy, "dan", times, std::nullopt);
    REQUIRE(labs.size() == 3);
    CHECK(labs[0].lab == "branching");
    CHECK(labs[0].late.daysLate == 1);
    CHECK(labs[0].late.slipDaysUsed == 1);
    CHECK(labs[0].late.penalty == 0);
    CHECK(labs[1].lab == "uniform");
    CHECK(labs[1].late.daysLate == 3);
    CHECK(labs[1].late.slipDaysUsed == 1); // what branching left of the two
    CHECK(labs[1].late.penalty == Approx(0.2));
    CHECK(labs[2].lab == "roulette");
    CHECK(labs[2].late.daysLate == 0);
    CHECK(lateLabsText(labs) == "branching 1 day(s) late (1 slip day(s)), uniform 3 day(s) late "
                                "(1 slip day(s))");
    // Lab scores 10 and 20 and 10: uniform's 20 loses 20%, 4 of 40 points.
    CHECK(totalPenalty(labs, {{"branching", 10}, {"uniform", 20}, {"roulette", 10}}) ==
          Approx(0.1));
    // The batch's --deadline for the labs without their own: importance is now 2 weeks late.
    CHECK(labLatenessOf(policy, "dan", times, first + 7 * week).size() == 4);
    // A lab dated 2^32 days after its deadline (a commit's date is the student's to set) is late
    // by a century at most: its late days never wrap into negative ones, which would add slip
    // days for the other labs.
    std::map<std::string, long long> wild = times;
    wild["branching"] = first + (1LL << 32) * kDay;
    const std::vector<LabLateness> wrapped = labLatenessOf(policy, "dan", wild, std::nullopt);
    CHECK(wrapped[0].late.daysLate == 36525);
    CHECK(wrapped[0].late.slipDaysUsed == 2);
    CHECK(wrapped[1].late.slipDaysUsed == 0);
    CHECK(wrapped[1].late.penalty == Approx(0.3));
    // Erin's 3 days on uniform: on time there, so both slip days are left for the rest.
    const std::vector<LabLateness> erin = labLatenessOf(policy, "erin", times, std::nullopt);
    CHECK(erin[1].late.daysLate == 0);
    CHECK(erin[0].late.daysLate == 1);
}

TEST_CASE("a late policy's deadlines per lab and a lab's own extension are checked, named when "
          "wrong",
          "[grader]") {
    const test::ScratchFolder scratch("late");
    const std::string rubric = (scratch.path / "rubric.json").string();
    const LatePolicy policy = readLatePolicy(
        {{"deadlines", {{"branching", "2026-10-02T23:59Z"}, {"mis", "2026-12-11T23:59Z"}}}},
        rubric);
    CHECK(policy.perLab());
    CHECK(policy.labDeadlines.at("branching") == *parseTime("2026-10-02T23:59Z"));
    CHECK(latePolicyFromJson(latePolicyJson(policy)).labDeadlines == policy.labDeadlines);
    CHECK(errorOf({{"deadlines", {{"lab7", "2026-10-02T23:59Z"}}}}, rubric)
              .find("late.deadlines names 'lab7', not a lab") != std::string::npos);
    CHECK(errorOf({{"deadlines", {{"uniform", "Friday"}}}}, rubric)
              .find("late.deadlines.uniform is \"Friday\", not a time") != std::string::npos);
    std::ofstream(scratch.path / "extensions.csv") << "id,days,lab\nerin@uni.edu,3,uniform\n";
    const LatePolicy extended = readLatePolicy(
        {{"deadlines", {{"uniform", "2026-10-09T23:59Z"}}}, {"extensions", "extensions.csv"}},
        rubric);
    CHECK(extended.labExtensionDays.at("erin_uni.edu").at("uniform") == 3);
    CHECK(latePolicyFromJson(latePolicyJson(extended)).labExtensionDays ==
          extended.labExtensionDays);
    CHECK(errorOf({{"extensions", "extensions.csv"}}, rubric)
              .find("needs a deadline per lab: late.deadlines") != std::string::npos);
    std::ofstream(scratch.path / "extensions.csv") << "erin,3,labs\n";
    CHECK(errorOf(
              {{"deadlines", {{"uniform", "2026-10-09T23:59Z"}}}, {"extensions", "extensions.csv"}},
              rubric)
              .find("extensions.csv:1: 'labs' is not a lab") != std::string::npos);
}

TEST_CASE("under a deadline per lab the gradebook takes each lab's own time, the LMS's over the "
          "submission's, and lowers each late lab's points",
          "[grader]") {
    const test::ScratchFolder scratch("late");
    GradingNow now = gradingWithPolicy();
    now.late.labDeadlines = {{"branching", *parseTime("2026-10-02T23:59Z")},
                             {"uniform", *parseTime("2026-10-09T23:59Z")}};
    // Lab files' own times: branching changed 2 days after its deadline, uniform on time; the
    // submission's time (the last commit) is later than both.
    auto result = [](long long uniformAt) {
        return nlohmann::json{
            {"status", "graded"},
            {"score", 40},
            {"max_score", 40},
            {"graded_under", {{"rubric_hash", "rubric"}, {"scenes_hash", "scenes"}}},
            {"labs", {{"branching", {{"score", 10}}}, {"uniform", {{"score", 30}}}}},
            {"intake",
             {{"submitted_at", *parseTime("2026-11-20T12:00Z")},
              {"time_source", "last commit"},
              {"taken",
               {{"branching.cpp", "labs/branching.cpp"}, {"uniform.cpp", "labs/uniform.cpp"}}},
              {"lab_times",
               {{"branching.cpp", *parseTime("2026-10-04T12:00Z")}, {"uniform.cpp", uniformAt}}}}}};
    };
    // hal's lab files have no time (none his submission could tell): not on time, unknown.
    nlohmann::json timeless = result(0);
    timeless["intake"].erase("submitted_at");
    timeless["intake"].erase("lab_times");
    // fay's uniform was changed after its deadline, but her LMS's hand-in of it was on time.
    now.times.byLab["fay"]["uniform"] = *parseTime("2026-10-09T20:00Z");
    const std::vector<GradebookEntry> entries = {
        {"eve", "", result(*parseTime("2026-10-09T12:00Z")), "", false, std::nullopt},
        {"fay", "", result(*parseTime("2026-10-12T12:00Z")), "", false, std::nullopt},
        {"gus", "", result(*parseTime("2026-10-12T12:00Z")), "", false, std::nullopt},
        {"hal", "", timeless, "", false, std::nullopt}};
    writeGradebook(scratch.path.string(), entries, now, std::nullopt);
    const std::string csv = readFile((scratch.path / "gradebook.csv").string());
    INFO(csv);
    CHECK(csv.find(",final_total,late_labs\n") != std::string::npos);
    // eve and fay: branching 2 days late, 1 slip day, 10% of its 10 points: 39 of 40.
    CHECK(csv.find(",yes,") != std::string::npos);
    CHECK(csv.find(",40,2,1,0.025,39,branching 2 day(s) late (1 slip day(s))\n") !=
          std::string::npos);
    // gus: uniform 3 days late too, with no slip day left: 30% of its 30 points, 9 more.
    CHECK(csv.find(",40,5,1,0.25,30,\"branching 2 day(s) late (1 slip day(s)), uniform 3 day(s) "
                   "late\"\n") != std::string::npos);
    CHECK(csv.find(",,last commit,unknown,") != std::string::npos);
    CHECK(csv.find(",40,0,0,0,40,\"branching: no time known, uniform: no time known\"\n") !=
          std::string::npos);
    CHECK(
        readFile((scratch.path / "summary.html").string()).find("1 handed in with no time known") !=
        std::string::npos);
    const std::string lms = readFile((scratch.path / "lms.csv").string());
    CHECK(lms.find("fay,fay,39\n") != std::string::npos);
    CHECK(lms.find("gus,gus,30\n") != std::string::npos);
}
