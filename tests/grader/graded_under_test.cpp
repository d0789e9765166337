// What a grade was made under, and what tells that it no longer fits: the scene files' hash, the
// rubric's, a stored reference's staleness, the submission times and the gradebook's maxima.
#include "catch.h"
#include "messages.h"

#include "checks/expectation.h"
#include "checks/rubric.h"
#include "common/content_hash.h"
#include "common/scene_files.h"
#include "reports/gradebook.h"
#include "reports/submission_time.h"

#include "pathlab/support/input_error.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <unistd.h>

using namespace pathlab;
using namespace pathlab::grader;
namespace fs = std::filesystem;

namespace {

/// A scratch folder, removed at the end of the test.
struct Scratch {
    fs::path path =
        fs::temp_directory_path() / ("pathlab-graded-under-" + std::to_string(::getpid()));
    Scratch() { fs::create_directories(path); }
    ~Scratch() { fs::remove_all(path); }
};

std::string readText(const fs::path& path) {
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

/// models/furnace.{ecs,obj,mtl} copied into `folder`; returns the .ecs.
std::string copyFurnace(const fs::path& folder) {
    for (const char* extension : {".ecs", ".obj", ".mtl"})
        fs::copy_file(fs::path(PATHLAB_MODELS_DIR) / (std::string("furnace") + extension),
                      folder / (std::string("furnace") + extension));
    return (folder / "furnace.ecs").string();
}

Rubric kitRubric() { return loadRubric(std::string(PATHLAB_GRADER_DIR) + "/rubric.json"); }

/// A reference for the scene at `ecs` with flat expectations (no renders needed to test keys).
SceneReference flatReference(const std::string& ecs, const Rubric& rubric) {
    SceneReference ref = referenceHeader("furnace", rubric, rubric.maxDepth, rubric.continueProb);
    ref.sceneFilesHash = sceneFilesHash(ecs);
    for (Expectation* e : {&ref.depthLimited, &ref.unbiased}) {
        e->solution = "test";
        e->seeds = 2, e->spp = 1;
        e->mean.assign(3, 1.0), e->standardError.assign(3, 0.1);
        e->image.assign(3 * static_cast<size_t>(rubric.width) * rubric.height, 1.0f);
    }
    return ref;
}

std::string staleWhy(const std::string& folder, const std::string& ecs, const Rubric& rubric) {
    return messageOf<StaleReference>([&] { loadReference(folder, ecs, rubric); });
}

} // namespace

TEST_CASE("a scene's files: the .ecs, the .obj it names and the .mtl that names", "[grader]") {
    Scratch scratch;
    const std::string ecs = copyFurnace(scratch.path);
    const std::vector<std::string> files = sceneFiles(ecs);
    REQUIRE(files.size() == 3);
    CHECK(fs::path(files[0]).filename() == "furnace.ecs");
    CHECK(fs::path(files[1]).filename() == "furnace.obj");
    CHECK(fs::path(files[2]).filename() == "furnace.mtl");

    const std::string before = sceneFilesHash(ecs);
    CHECK(sceneFilesHash(ecs) == before);
    std::ofstream(scratch.path / "furnace.mtl", std::ios::app) << "\n# the light changed\n";
    CHECK(sceneFilesHash(ecs) != before);
}

TEST_CASE("a scene's material library whose name has spaces is one of its files", "[grader]") {
    Scratch scratch;
    std::ofstream(scratch.path / "s.ecs") << "-i model.obj\n-vp 0 0 -2 -vi 0 0 0\n";
    std::ofstream(scratch.path / "my materials.mtl") << "newmtl red\nKd 0.8 0.1 0.1\n";
    std::ofstream(scratch.path / "model.obj")
        << "mtllib my materials.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n";
    const std::vector<std::string> files = sceneFiles((scratch.path / "s.ecs").string());
    REQUIRE(files.size() == 3);
    CHECK(fs::path(files[2]).filename() == "my materials.mtl");
}

TEST_CASE("a stored reference is stale when its scene files, the rubric's sizes or the kit change",
          "[grader]") {
    Scratch scratch;
    const std::string ecs = copyFurnace(scratch.path);
    const std::string references = (scratch.path / "references").string();
    fs::create_directories(references);
    const Rubric rubric = kitRubric();
    saveReference(references, flatReference(ecs, rubric));
    CHECK(staleWhy(references, ecs, rubric).empty());
    CHECK(loadReference(references, ecs, rubric).sceneFilesHash == sceneFilesHash(ecs));

    SECTION("an edited .mtl") {
        std::ofstream(scratch.path / "furnace.mtl", std::ios::app) << "\n# Ke doubled\n";
        const std::string why = staleWhy(references, ecs, rubric);
        CHECK(why.find("the scene's files") != std::string::npos);
    }
    SECTION("another image size in the rubric") {
        Rubric wider = rubric;
        wider.width = 2 * rubric.width;
        CHECK(staleWhy(references, ecs, wider).find("the rubric's image size") !=
              std::string::npos);
        Rubric moreSeeds = rubric; // more precise, the same expectation: not stale
        moreSeeds.seeds = 2 * rubric.seeds;
        CHECK(staleWhy(references, ecs, moreSeeds).empty());
    }
    SECTION("another kit version") {
        nlohmann::json j = nlohmann::json::parse(readText(fs::path(references) / "furnace.json"));
        j["kit_version"] = "0.0.1";
        std::ofstream(fs::path(references) / "furnace.json") << j.dump();
        CHECK(staleWhy(references, ecs, rubric).find("PathLab 0.0.1") != std::string::npos);
    }
    SECTION("a reference from before the keys existed is stale, a missing one is not there") {
        nlohmann::json j = nlohmann::json::parse(readText(fs::path(references) / "furnace.json"));
        j.erase("scene_files_hash");
        std::ofstream(fs::path(references) / "furnace.json") << j.dump();
        CHECK_FALSE(staleWhy(references, ecs, rubric).empty());
        fs::remove(fs::path(references) / "furnace.json");
        bool stale = false, missing = false;
        try {
            loadReference(references, ecs, rubric);
        } catch (const StaleReference&) {
            stale = true;
        } catch (const InputError& e) {
            missing = std::string(e.what()).find("no stored reference") != std::string::npos;
        }
        CHECK(missing);
        CHECK_FALSE(stale);
    }
}

TEST_CASE("the kit's stored references fit the kit's scenes and rubric", "[grader]") {
    const Rubric rubric = kitRubric();
    for (const std::string& scene : rubric.scenes) {
        INFO(scene);
        const std::string ecs = std::string(PATHLAB_MODELS_DIR) + "/" + scene + ".ecs";
        CHECK(staleWhy(std::string(PATHLAB_GRADER_DIR) + "/references", ecs, rubric).empty());
    }
}

TEST_CASE("the rubric's hash: its settings, not its layout or its 'about'", "[grader]") {
    Scratch scratch;
    nlohmann::json j =
        nlohmann::json::parse(readText(std::string(PATHLAB_GRADER_DIR) + "/rubric.json"));
    const std::string path = (scratch.path / "rubric.json").string();
    auto hashOf = [&](const nlohmann::json& rubric, int indent) {
        std::ofstream(path) << rubric.dump(indent);
        return loadRubric(path).hash;
    };
    const std::string kit = kitRubric().hash;
    CHECK(hashOf(j, 4) == kit);
    j["about"] = "edited by the instructor";
    CHECK(hashOf(j, -1) == kit);
    j["points"]["roulette"]["speed"] = 7;
    CHECK(hashOf(j, 1) != kit);
}

TEST_CASE("content hashes tell pieces apart", "[grader]") {
    CHECK(ContentHash().add("ab").add("c").hex() != ContentHash().add("a").add("bc").hex());
    CHECK(ContentHash().add("x").hex().size() == 16);
}

TEST_CASE("submission times: ISO 8601 with a zone, a deadline in local time, an LMS's CSV",
          "[grader]") {
    CHECK(parseTime("2026-12-01T23:59Z") == 1796169540LL);
    CHECK(parseTime("2026-12-01T23:59:30Z") == 1796169570LL);
    CHECK(parseTime("2026-12-02T00:59+01:00") == 1796169540LL);
    CHECK(parseTime("2026-12-01T18:59-05:00") == 1796169540LL);
    CHECK(parseTime("2026-12-01T23:59").has_value());
    CHECK_FALSE(parseTime("yesterday").has_value());
    CHECK_FALSE(parseTime("2026-13-01T00:00Z").has_value());
    CHECK_FALSE(parseTime("2026-12-01T23:59+1").has_value());
    CHECK_FALSE(parseTime("2026-02-30T23:59").has_value()); // no such day
    CHECK(parseTime("2028-02-29T12:00Z").has_value());
    CHECK(isoTime(1796169540LL) == "2026-12-01T23:59:00Z");

    Scratch scratch;
    const fs::path csv = scratch.path / "times.csv";
    std::ofstream(csv)
        << "id,submitted_at\nalice,2026-12-01T10:00:00Z\r\nbob,2026-12-02T10:00:00Z\n"
           "bob,uniform,2026-12-03T10:00:00Z\n";
    const auto times = loadSubmissionTimes(csv.string());
    CHECK(times.whole.at("alice") == *parseTime("2026-12-01T10:00Z"));
    CHECK(times.whole.at("bob") == *parseTime("2026-12-02T10:00Z"));
    CHECK(times.byLab.at("bob").at("uniform") == *parseTime("2026-12-03T10:00Z")); // one lab's
    auto errorOf = [&] {
        try {
            loadSubmissionTimes(csv.string());
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    std::ofstream(csv) << "id,submitted_at\nalice,soon\n";
    CHECK(errorOf().find("times.csv:2") != std::string::npos);
    std::ofstream(csv) << "dave,yesterday\n"; // a first line is a header only if it says id
    CHECK(errorOf().find("times.csv:1") != std::string::npos);
    std::ofstream(csv) << "id,lab,submitted_at\ndave,lab9,2026-12-01T10:00:00Z\n";
    CHECK(errorOf().find("times.csv:2: 'lab9' is not a lab") != std::string::npos);
}

TEST_CASE("a gradebook never mixes maxima, says pending, stale and late", "[grader]") {
    Scratch scratch;
    GradingNow now;
    now.rubricHash = "rubric-now";
    now.scenesHash = "scenes-now";
    now.maxScore = 40;
    now.deadline = parseTime("2026-12-01T23:59Z");
    auto result = [](double score, double max, const std::string& rubric,
                     const std::string& submitted) {
        return nlohmann::json{
            {"status", "graded"},
            {"score", score},
            {"max_score", max},
            {"labs", nlohmann::json::object()},
            {"missing_labs", nlohmann::json::array()},
            {"graded_under", {{"rubric_hash", rubric}, {"scenes_hash", "scenes-now"}}},
            {"intake",
             {{"submitted_at", *parseTime(submitted)},
              {"time_source", "last commit"},
              {"commit", "abc123"},
              {"files_hash", "f00d"}}}};
    };
    std::vector<GradebookEntry> entries = {
        {"alice", "", result(40, 40, "rubric-now", "2026-12-01T12:00Z"), "", false, std::nullopt},
        {"bob", "", result(50, 60, "rubric-before", "2026-12-02T12:00Z"), "", false, std::nullopt},
        {"carol", "", result(30, 40, "rubric-before", "2026-12-01T12:00Z"), "", false,
         std::nullopt},
        {"dave", "", nullptr, "", true, std::nullopt},
    };
    CHECK(staleness(entries[0].result, now).empty());
    CHECK(staleness(entries[1].result, now) == "graded under another rubric");
    writeGradebook(scratch.path.string(), entries, now,
                   std::vector<SimilarLabs>{{"alice", "reference solutions", "uniform", 0.97}});

    std::istringstream csv(readText(scratch.path / "gradebook.csv"));
    std::string header, line;
    std::getline(csv, header);
    std::vector<std::string> columns;
    for (std::istringstream h(header); std::getline(h, line, ',');) columns.push_back(line);
    const auto column = [&](const std::string& name) {
        return std::find(columns.begin(), columns.end(), name) - columns.begin();
    };
    std::map<std::string, std::vector<std::string>> rows;
    while (std::getline(csv, line)) {
        std::vector<std::string> fields;
        bool quoted = false;
        std::string field;
        for (char c : line) {
            if (c == '"')
                quoted = !quoted;
            else if (c == ',' && !quoted)
                fields.push_back(field), field.clear();
            else
                field += c;
        }
        fields.push_back(field);
        rows[fields[0]] = fields;
    }
    // The first gradebooks' columns, where scripts outside the kit read them by position: the
    // labs added since come after the status.
    REQUIRE(columns.size() > 8);
    CHECK(std::vector<std::string>(columns.begin(), columns.begin() + 8) ==
          std::vector<std::string>{"id", "branching", "uniform", "importance", "roulette", "total",
                                   "max_total", "status"});
    CHECK(column("glossy") == 8);
    CHECK(column("mis") == 9);
    REQUIRE(rows.size() == 4);
    for (const auto& [id, fields] : rows) {
        INFO(id);
        REQUIRE(fields.size() == columns.size());
        CHECK(fields[column("max_total")] == "40");
    }
    CHECK(rows["alice"][column("total")] == "40");
    CHECK(rows["alice"][column("late")] == "no");
    CHECK(rows["alice"][column("commit")] == "abc123");
    CHECK(rows["bob"][column("total")].empty()); // out of 60: never shown beside totals out of 40
    CHECK(rows["bob"][column("status")].find("stale") == 0);
    CHECK(rows["bob"][column("late")] == "yes");
    CHECK(rows["carol"][column("total")] == "30"); // kept, same maximum, marked stale
    CHECK(rows["carol"][column("status")].find("stale: graded under another rubric") == 0);
    CHECK(rows["dave"][column("status")] == "pending");

    const std::string lms = readText(scratch.path / "lms.csv");
    CHECK(lms.find("Student,SIS Login ID,PathLab (40 points)\n") == 0);
    CHECK(lms.find("alice,alice,40\n") != std::string::npos);
    CHECK(lms.find("bob") == std::string::npos);
    // Stale or pending, a total is not what the grading now gives: withheld, never exported.
    CHECK(lms.find("carol") == std::string::npos);
    CHECK(lms.find("dave") == std::string::npos);

    const std::string summary = readText(scratch.path / "summary.html");
    CHECK(summary.find("1 pending, 2 stale") != std::string::npos);
    CHECK(summary.find("<tr><td>uniform</td><td>2</td><td>1</td><td>97%</td>") !=
          std::string::npos);
    // A histogram per lab, beside the totals'.
    size_t charts = 0;
    for (size_t at = summary.find(" score, % of its maximum"); at != std::string::npos;
         at = summary.find(" score, % of its maximum", at + 1))
        ++charts;
    CHECK(charts == LabCount);
    CHECK(summary.find("mis score, % of its maximum") != std::string::npos);
    CHECK(readText(scratch.path / "similarity.csv") ==
          "lab,first,second,similarity\nuniform,alice,reference solutions,0.97\n");
}

TEST_CASE("a result whose rubric changed only in points or thresholds is re-scored; one whose "
          "scenes, kit, measurement settings or speed changed is graded again",
          "[grader]") {
    GradingNow now;
    now.rubricHash = "rubric-now";
    now.measurementHash = "measured-alike";
    now.scenesHash = "scenes-now";
    now.maxScore = 40;
    const auto result = [](const std::string& rubric, const std::string& measured,
                           const std::string& scenes, bool speed) {
        return nlohmann::json{{"max_score", 40},
                              {"graded_under",
                               {{"rubric_hash", rubric},
                                {"measurement_hash", measured},
                                {"scenes_hash", scenes},
                                {"speed_measured", speed},
                                {"kit_version", PATHLAB_VERSION}}}};
    };
    CHECK(regradeNeeded(result("rubric-now", "measured-alike", "scenes-now", true), now) ==
          Regrade::None);
    CHECK(regradeNeeded(result("rubric-before", "measured-alike", "scenes-now", true), now) ==
          Regrade::Rescore);
    CHECK(regradeNeeded(result("rubric-before", "measured-otherwise", "scenes-now", true), now) ==
          Regrade::Measure);
    CHECK(regradeNeeded(result("rubric-now", "measured-alike", "scenes-before", true), now) ==
          Regrade::Measure);
    // Graded without speed, now with: its timed runs must be made.
    CHECK(regradeNeeded(result("rubric-before", "measured-alike", "scenes-now", false), now) ==
          Regrade::Measure);
    // A result of before measurements were kept has no measurement hash: graded again.
    nlohmann::json old = result("rubric-before", "measured-alike", "scenes-now", true);
    old["graded_under"].erase("measurement_hash");
    CHECK(regradeNeeded(old, now) == Regrade::Measure);
}
