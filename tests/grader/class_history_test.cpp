// The class over the term (reports/class_history.h): a finished batch adds the class's figures to
// history.jsonl and a batch still running does not; the figures are the means of the graded
// results; a line cut short is left out; and the summary's chart keeps its points in its box.
#include "catch.h"
#include "test_support.h"

#include "reports/class_history.h"
#include "reports/gradebook.h"

#include "pathlab/support/whole_file.h"

#include <fstream>
#include <regex>

using namespace pathlab;
using namespace pathlab::grader;

namespace {

/// A result of `total` out of 40: branching `branching` of 10 (its correctness passed when
/// positive), uniform the rest out of 30.
nlohmann::json result(double branching, double total) {
    auto lab = [](double score, double max) {
        return nlohmann::json{{"score", score},
                              {"max_score", max},
                              {"checks", {{"correctness", {{"passed", score > 0}}}}}};
    };
    return {{"status", "graded"},
            {"score", total},
            {"max_score", 40},
            {"graded_under", {{"rubric_hash", "rubric"}, {"scenes_hash", "scenes"}}},
            {"labs", {{"branching", lab(branching, 10)}, {"uniform", lab(total - branching, 30)}}}};
}

GradingNow gradingNow() {
    GradingNow now;
    now.rubricHash = "rubric";
    now.scenesHash = "scenes";
    now.maxScore = 40;
    return now;
}

} // namespace

TEST_CASE("the class's figures: the mean total and each lab's mean and correctness pass rate",
          "[grader]") {
    const std::vector<GradebookEntry> entries = {
        {"ann", "", result(10, 40), "", false, std::nullopt},
        {"bo", "", result(0, 20), "", false, std::nullopt},
        {"cy", "", nullptr, "no result", false, std::nullopt}}; // not graded: not counted
    const ClassFigures f = classFiguresNow(entries, gradingNow(), "2026-10-05T12:00:00Z");
    CHECK(f.graded == 2);
    CHECK(f.submissions == 3);
    CHECK(f.meanTotal == Approx(75));                 // (40 + 20) / 2 of 40
    CHECK(f.labMean.at("branching") == Approx(50));   // (10 + 0) / 2 of 10
    CHECK(f.labMean.at("uniform") == Approx(83.333)); // (30 + 20) / 2 of 30
    CHECK(f.labCorrectness.at("branching") == Approx(50));
    CHECK(f.labCorrectness.at("importance") == 0);
}

TEST_CASE("a finished batch adds a point to the class's history, a running one does not, and the "
          "summary draws them",
          "[grader]") {
    const test::ScratchFolder scratch("history");
    const std::string out = scratch.path.string();
    const GradingNow now = gradingNow();
    const std::vector<SimilarLabs> none;
    writeGradebook(out, {{"ann", "", result(0, 10), "", false, std::nullopt}}, now, none);
    writeGradebook(out, {{"ann", "", result(10, 30), "", false, std::nullopt}}, now, std::nullopt);
    CHECK(readClassHistory(out).size() == 1); // the batch still running added nothing
    std::string summary = readFile(out + "/summary.html");
    CHECK(summary.find("<h2>Over time</h2>") != std::string::npos);
    CHECK(summary.find("One batch so far") != std::string::npos);
    writeGradebook(out, {{"ann", "", result(10, 40), "", false, std::nullopt}}, now, none);
    std::ofstream(out + "/history.jsonl", std::ios::app) << "{\"at\": \"2026-10-\n"; // cut short
    writeGradebook(out, {{"ann", "", result(10, 40), "", false, std::nullopt}}, now, none);
    const std::vector<ClassFigures> history = readClassHistory(out);
    REQUIRE(history.size() == 3);
    CHECK(history[0].meanTotal == Approx(25));
    CHECK(history[1].meanTotal == Approx(100));
    summary = readFile(out + "/summary.html");
    INFO(summary);
    CHECK(summary.find("<polyline") != std::string::npos);
    CHECK(summary.find("<td>25%</td>") != std::string::npos);
    CHECK(summary.find("<td>100%</td>") != std::string::npos);
    // Every point of every line inside the chart's 640x250 box.
    const std::regex point(R"((-?\d+),(-?\d+) )");
    int points = 0;
    for (auto it = std::sregex_iterator(summary.begin(), summary.end(), point);
         it != std::sregex_iterator(); ++it, ++points) {
        CHECK(std::stoi((*it)[1]) >= 0);
        CHECK(std::stoi((*it)[1]) <= 640);
        CHECK(std::stoi((*it)[2]) >= 0);
        CHECK(std::stoi((*it)[2]) <= 250);
    }
    CHECK(points == 3 * 7); // three batches, the total and six labs
}
