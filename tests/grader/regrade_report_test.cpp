// A regrade's report (reports/regrade_report.h) and what the gradebook does with a total a
// regrade lowered (the rubric's regrades.lower_scores), on result.json files written here as a
// batch writes them: the grading now in submissions/ID/, the ones before in attempts/N/.
#include "catch.h"
#include "test_support.h"

#include "checks/rubric.h"
#include "reports/gradebook.h"
#include "reports/regrade_report.h"

#include "pathlab/support/input_error.h"

#include "pathlab/support/whole_file.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace pathlab;
using namespace pathlab::grader;
namespace fs = std::filesystem;

namespace {

/// A result.json of one lab, uniform, with its correctness and noise points.
nlohmann::json result(int attempt, double correctness, double noise, const std::string& rubric,
                      const std::string& files = "f00d") {
    return {{"status", "graded"},
            {"attempt", attempt},
            {"score", correctness + noise},
            {"max_score", 10},
            {"labs",
             {{"uniform",
               {{"score", correctness + noise},
                {"max_score", 10},
                {"checks",
                 {{"correctness", {{"score", correctness}, {"passed", correctness > 0}}},
                  {"noise", {{"score", noise}, {"passed", noise > 0}}}}}}}}},
            {"graded_under",
             {{"rubric_hash", rubric},
              {"measurement_hash", "measured-alike"},
              {"scenes_hash", "scenes"},
              {"kit_version", "0.1.0"},
              {"speed_measured", false}}},
            {"intake", {{"files_hash", files}, {"commit", ""}}}};
}

void write(const fs::path& path, const nlohmann::json& j) {
    fs::create_directories(path.parent_path());
    std::ofstream(path) << j.dump(1);
}

/// A submission graded `results.size()` times, the last one the grading now.
void gradings(const fs::path& out, const std::string& id,
              const std::vector<nlohmann::json>& results) {
    const fs::path folder = out / "submissions" / id;
    for (size_t i = 0; i + 1 < results.size(); ++i)
        write(folder / "attempts" / std::to_string(i + 1) / "result.json", results[i]);
    write(folder / "result.json", results.back());
}

GradingNow gradingNow(LowerScores lowerScores) {
    GradingNow now;
    now.rubricHash = "rubric-now";
    now.scenesHash = "scenes";
    now.maxScore = 10;
    now.lowerScores = lowerScores;
    return now;
}

/// The class below: alice lowered by a rubric's thresholds (10 -> 6, her noise points gone),
/// bob raised (6 -> 10), carol's own resubmission lower (10 -> 6), dave graded once.
void gradeClass(const fs::path& out) {
    gradings(out, "alice", {result(1, 6, 4, "rubric-before"), result(2, 6, 0, "rubric-now")});
    gradings(out, "bob", {result(1, 6, 0, "rubric-before"), result(2, 6, 4, "rubric-now")});
    gradings(out, "carol",
             {result(1, 6, 4, "rubric-now", "f00d"), result(2, 6, 0, "rubric-now", "beef")});
    gradings(out, "dave", {result(1, 6, 4, "rubric-now")});
}

std::vector<GradebookEntry> entries(const fs::path& out) {
    std::vector<GradebookEntry> all;
    for (const char* id : {"alice", "bob", "carol", "dave"})
        all.push_back(readGradebookEntry(out.string(), id, ""));
    return all;
}

/// gradebook.csv's rows by id, each a map from column to field (no field here is quoted).
std::map<std::string, std::map<std::string, std::string>> gradebookRows(const fs::path& out) {
    std::istringstream csv(readFile((out / "gradebook.csv").string()));
    std::string line, field;
    std::getline(csv, line);
    std::vector<std::string> columns;
    for (std::istringstream h(line); std::getline(h, field, ',');) columns.push_back(field);
    std::map<std::string, std::map<std::string, std::string>> rows;
    while (std::getline(csv, line)) {
        std::vector<std::string> fields;
        bool quoted = false;
        field.clear();
        for (char c : line) {
            if (c == '"')
                quoted = !quoted;
            else if (c == ',' && !quoted)
                fields.push_back(field), field.clear();
            else
                field += c;
        }
        fields.push_back(field);
        for (size_t i = 0; i < columns.size() && i < fields.size(); ++i)
            rows[fields[0]][columns[i]] = fields[i];
    }
    return rows;
}

} // namespace

TEST_CASE("a regrade is compared with the attempt before it, check by check, with its reason",
          "[grader]") {
    const test::ScratchFolder scratch("regrades");
    gradeClass(scratch.path);
    const fs::path submissions = scratch.path / "submissions";
    const auto alice = compareWithAttemptBefore(
        "alice", (submissions / "alice").string(),
        nlohmann::json::parse(readFile((submissions / "alice" / "result.json").string())));
    REQUIRE(alice);
    CHECK(alice->fromAttempt == 1);
    CHECK(alice->toAttempt == 2);
    CHECK(alice->before == 10);
    CHECK(alice->after == 6);
    CHECK_FALSE(alice->resubmitted);
    REQUIRE(alice->reasons.size() == 1);
    CHECK(alice->reasons[0] == "the rubric's points or thresholds changed");
    REQUIRE(alice->changes.size() == 1); // correctness kept its 6 points: not a change
    CHECK(alice->changes[0].lab == "uniform");
    CHECK(alice->changes[0].check == "noise");
    CHECK(alice->changes[0].before == 4.0);
    CHECK(alice->changes[0].after == 0.0);
    CHECK(regradeLine(*alice) == "alice: attempt 1 -> 2 (the rubric's points or thresholds "
                                 "changed): 10 / 10 -> 6 / 10; uniform noise 4 -> 0");

    const auto carol = compareWithAttemptBefore(
        "carol", (submissions / "carol").string(),
        nlohmann::json::parse(readFile((submissions / "carol" / "result.json").string())));
    REQUIRE(carol);
    CHECK(carol->resubmitted);
    CHECK(carol->reasons == std::vector<std::string>{"the submission's files changed"});
    CHECK_FALSE(compareWithAttemptBefore(
        "dave", (submissions / "dave").string(),
        nlohmann::json::parse(readFile((submissions / "dave" / "result.json").string()))));

    // The same files graded again with nothing changed: said as asked for, not as a cause.
    gradings(scratch.path, "erin", {result(1, 6, 4, "rubric-now"), result(2, 6, 4, "rubric-now")});
    const auto erin = compareWithAttemptBefore(
        "erin", (submissions / "erin").string(),
        nlohmann::json::parse(readFile((submissions / "erin" / "result.json").string())));
    REQUIRE(erin);
    CHECK(erin->changes.empty());
    CHECK(erin->reasons[0].find("graded again as asked") == 0);
}

TEST_CASE("a lowered total waits for the rubric's choice; replace and keep_higher decide it",
          "[grader]") {
    const test::ScratchFolder scratch("regrades");
    gradeClass(scratch.path);
    const std::string out = scratch.path.string();
    const std::vector<GradebookEntry> all = entries(scratch.path);
    REQUIRE(all[0].higherEarlier);
    CHECK(all[0].higherEarlier->score == 10);
    CHECK(all[0].higherEarlier->attempt == 1);
    CHECK_FALSE(all[1].higherEarlier); // raised
    CHECK_FALSE(all[2].higherEarlier); // lower, but her own new files
    CHECK_FALSE(all[3].higherEarlier); // graded once

    SECTION("undecided: the gradebook shows the new total and says so; the LMS keeps its own") {
        writeGradebook(out, all, gradingNow(LowerScores::Undecided), std::nullopt);
        auto rows = gradebookRows(scratch.path);
        CHECK(rows["alice"]["total"] == "6");
        CHECK(rows["alice"]["graded_total"] == "6");
        CHECK(rows["alice"]["status"].find("a regrade lowered the total from 10 (attempt 1) to 6: "
                                           "withheld from lms.csv") != std::string::npos);
        const std::string lms = readFile((scratch.path / "lms.csv").string());
        CHECK(lms.find("alice") == std::string::npos);
        CHECK(lms.find("bob,bob,10\n") != std::string::npos);
        CHECK(lms.find("carol,carol,6\n") != std::string::npos);
        const std::string summary = readFile((scratch.path / "summary.html").string());
        CHECK(summary.find("1 total(s) lowered by a regrade") != std::string::npos);
        // The class page's labs: uniform's mean over the four (6, 10, 6, 10) and its pass rates.
        CHECK(summary.find("<tr><td>uniform</td><td>8 / 10</td><td>100% (4 of 4)</td><td>50% (2 "
                           "of 4)</td><td>not checked</td></tr>") != std::string::npos);
    }
    SECTION("replace: the lower total counts") {
        writeGradebook(out, all, gradingNow(LowerScores::Replace), std::nullopt);
        CHECK(gradebookRows(scratch.path)["alice"]["total"] == "6");
        CHECK(readFile((scratch.path / "lms.csv").string()).find("alice,alice,6\n") !=
              std::string::npos);
    }
    SECTION("keep_higher: the higher earlier total of the same files counts") {
        writeGradebook(out, all, gradingNow(LowerScores::KeepHigher), std::nullopt);
        auto rows = gradebookRows(scratch.path);
        CHECK(rows["alice"]["total"] == "10");
        CHECK(rows["alice"]["graded_total"] == "6");
        CHECK(rows["alice"]["status"].find("kept the total 10 (attempt 1)") != std::string::npos);
        CHECK(rows["carol"]["total"] == "6"); // a resubmission's own total, lower or not
        CHECK(readFile((scratch.path / "lms.csv").string()).find("alice,alice,10\n") !=
              std::string::npos);
    }
    // regrades.csv: a total row and a row per changed check, for every regraded submission.
    const std::string regrades = readFile((scratch.path / "regrades.csv").string());
    CHECK(regrades.find("id,from_attempt,to_attempt,lab,check,before,after,max_before,max_after,"
                        "reason\n") == 0);
    CHECK(regrades.find("alice,1,2,total,total,10,6,10,10,the rubric's points or thresholds "
                        "changed\n") != std::string::npos);
    CHECK(regrades.find("alice,1,2,uniform,noise,4,0,,,the rubric's points or thresholds "
                        "changed\n") != std::string::npos);
    CHECK(regrades.find("bob,1,2,uniform,noise,0,4,") != std::string::npos);
    CHECK(regrades.find("carol,1,2,total,total,10,6,10,10,the submission's files changed\n") !=
          std::string::npos);
    CHECK(regrades.find("dave") == std::string::npos);
}

TEST_CASE("the rubric's regrades.lower_scores is read, named when wrong, and stales nothing",
          "[grader]") {
    const test::ScratchFolder scratch("regrades");
    nlohmann::json kit = nlohmann::json::parse(readFile(PATHLAB_GRADER_DIR "/rubric.json"));
    const std::string path = (scratch.path / "rubric.json").string();
    std::ofstream(path) << kit.dump();
    const Rubric plain = loadRubric(path);
    CHECK(plain.lowerScores == LowerScores::Undecided);
    kit["regrades"] = {{"lower_scores", "keep_higher"}};
    std::ofstream(path) << kit.dump();
    const Rubric chosen = loadRubric(path);
    CHECK(chosen.lowerScores == LowerScores::KeepHigher);
    CHECK(chosen.hash == plain.hash); // choosing re-grades and re-scores nobody
    kit["regrades"] = {{"lower_scores", "never"}};
    std::ofstream(path) << kit.dump();
    try {
        loadRubric(path);
        FAIL("a rubric with regrades.lower_scores 'never' was taken");
    } catch (const InputError& e) {
        CHECK(std::string(e.what()).find("regrades.lower_scores is 'never'; it must be replace") !=
              std::string::npos);
    }
}
