// Per-student variants (checks/student_variant.h): each student's furnace and box drawn from the
// class secret and their id, the same every time and within the rubric's ranges; the furnace's
// reference is its analytic value for the drawn albedo, emission and depth; the rubric's words
// for a wrong setting or a missing secret; and what the hashes see of the secret.
#include "catch.h"
#include "test_support.h"

#include "checks/grading_scenes.h"
#include "checks/rubric.h"
#include "checks/rubric_text.h"
#include "checks/scene_variants.h"
#include "checks/student_variant.h"
#include "common/plain_id.h"

#include "pathlab/support/input_error.h"
#include "pathlab/support/whole_file.h"

#include <cmath>
#include <filesystem>
#include <functional>
#include <random>
#include <set>
#include <sstream>

using namespace pathlab;
using namespace pathlab::grader;
using pathlab::test::ScratchFolder;
namespace fs = std::filesystem;

namespace {

VariantSettings settings(const std::string& secretFile) {
    VariantSettings s;
    s.perStudent = true;
    s.secretFile = secretFile;
    return s;
}

std::string errorOf(const nlohmann::json& section) {
    try {
        readVariantSettings(section, "/course/rubric.json");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

/// The kit's rubric with `variants` as its section, written into `folder`.
std::string rubricWith(const fs::path& folder, const nlohmann::json& variants) {
    nlohmann::json j =
        nlohmann::json::parse(readFile(std::string(PATHLAB_GRADER_DIR) + "/rubric.json"));
    j["variants"] = variants;
    const std::string path = (folder / "rubric.json").string();
    writeFileAtomically(path, j.dump(1));
    return path;
}

} // namespace

TEST_CASE("a student's variant is the same every time, apart from another's, within the ranges",
          "[grader]") {
    const VariantSettings s = settings("unused");
    const std::string secret = "a class secret of the instructor's";
    const StudentVariant alice = drawStudentVariant(s, secret, "alice");
    const StudentVariant again = drawStudentVariant(s, secret, "alice");
    CHECK(alice.furnace.reflectance == again.furnace.reflectance);
    CHECK(alice.furnace.emission == again.furnace.emission);
    CHECK(alice.furnace.maxDepth == again.furnace.maxDepth);
    CHECK(alice.boxSeed == again.boxSeed);
    // Another secret, another variant: the secret, not the id alone, decides it.
    CHECK(drawStudentVariant(s, secret + "!", "alice").boxSeed != alice.boxSeed);

    std::set<double> albedos;
    std::set<int> depths;
    for (int k = 0; k < 200; ++k) {
        const StudentVariant v = drawStudentVariant(s, secret, "student" + std::to_string(k));
        CHECK(v.furnace.reflectance >= s.albedo.low);
        CHECK(v.furnace.reflectance <= s.albedo.high);
        CHECK(v.furnace.emission >= s.emission.low);
        CHECK(v.furnace.emission <= s.emission.high);
        CHECK(v.furnace.maxDepth >= 2);
        CHECK(v.furnace.maxDepth <= 6);
        albedos.insert(v.furnace.reflectance);
        depths.insert(v.furnace.maxDepth);
    }
    // 200 students share few answers: many albedos (3 decimals), every depth of the range.
    CHECK(albedos.size() > 150);
    CHECK(depths.size() == 5);
}

TEST_CASE("a student's furnace is written with its numbers and graded at its analytic value",
          "[grader]") {
    ScratchFolder scratch("student-variant");
    Rubric rubric = loadRubric(std::string(PATHLAB_GRADER_DIR) + "/rubric.json");
    rubric.variants = settings("unused");
    StudentVariant v;
    v.id = "alice";
    v.furnace.reflectance = 0.4;
    v.furnace.emission = 1.5;
    v.furnace.maxDepth = 4;
    const std::vector<GradingScene> scenes =
        studentVariantScenes(rubric, v, (scratch.path / "variant").string(), {}, "", "");
    REQUIRE(scenes.size() == 1); // no box scene in the settings
    const GradingScene& furnace = scenes[0];
    CHECK(furnace.name == "your furnace (albedo 0.4, Le 1.5, maxDepth 4)");
    REQUIRE(furnace.parameters);
    CHECK(furnace.parameters->maxDepth == 4);
    const std::string mtl = readFile((scratch.path / "variant" / "furnace_furnace.mtl").string());
    CHECK(mtl.find("Kd 0.40000000000000002 0.40000000000000002 0.40000000000000002") !=
          std::string::npos);
    CHECK(mtl.find("Ke 1.5 1.5 1.5") != std::string::npos);
    // Le·(1 − a^(D+2))/(1 − a) for a depth-limited lab, Le/(1 − a) for an unbiased one.
    const double a = 0.4, Le = 1.5;
    const double depthLimited = Le * (1 - std::pow(a, 6)) / (1 - a), unbiased = Le / (1 - a);
    for (double mean : furnace.reference.depthLimited.mean) CHECK(mean == Approx(depthLimited));
    for (double mean : furnace.reference.unbiased.mean) CHECK(mean == Approx(unbiased));
    for (double se : furnace.reference.unbiased.standardError) CHECK(se == 0);
}

TEST_CASE("the rubric's variants section: its words for a wrong setting", "[grader]") {
    CHECK(errorOf({{"per_student", true}, {"secret_file", 7}})
              .find("variants.secret_file must name the file") != std::string::npos);
    // A release's rubric, its secret's name left out, is read; the secret is asked for where used.
    const VariantSettings released =
        readVariantSettings({{"per_student", true}}, "/course/rubric.json");
    CHECK(released.perStudent);
    CHECK(released.secretFile.empty());
    try {
        classSecret(released);
        FAIL("a secret was found without its file's name");
    } catch (const InputError& e) {
        CHECK(std::string(e.what()).find("needs variants.secret_file") != std::string::npos);
    }
    CHECK(errorOf({{"per_student", true},
                   {"secret_file", "s.txt"},
                   {"furnace", {{"albedo", {0.5, 0.95}}}}})
              .find("variants.furnace.albedo must lie within [0.05, 0.9]") != std::string::npos);
    CHECK(
        errorOf(
            {{"per_student", true}, {"secret_file", "s.txt"}, {"furnace", {{"max_depth", {6, 2}}}}})
            .find("low <= high") != std::string::npos);
    CHECK(errorOf({{"per_student", true}, {"secret_file", "s.txt"}, {"box", {{"light", 2}}}})
              .find("variants.box.scene must name a public scene") != std::string::npos);
    const VariantSettings s = readVariantSettings(
        {{"per_student", true}, {"secret_file", "keys/s.txt"}}, "/course/rubric.json");
    CHECK(s.secretFile == "/course/keys/s.txt");
    CHECK(errorOf({{"per_student", false}}).empty());
}

TEST_CASE("the class secret: missing or short, the words say how to make one; the scenes' hash "
          "follows its text, the rubric's does not follow its file's name",
          "[grader]") {
    ScratchFolder scratch("class-secret");
    const std::string secretFile = (scratch.path / "secret.txt").string();
    try {
        classSecret(settings(secretFile));
        FAIL("a missing secret file was taken");
    } catch (const InputError& e) {
        CHECK(std::string(e.what()).find("does not exist: write a secret of your own") !=
              std::string::npos);
    }
    writeFileAtomically(secretFile, "short\n");
    try {
        classSecret(settings(secretFile));
        FAIL("a 5-character secret was taken");
    } catch (const InputError& e) {
        CHECK(std::string(e.what()).find("holds 5 characters") != std::string::npos);
    }
    writeFileAtomically(secretFile, "0123456789abcdef-first\n");
    CHECK(classSecret(settings(secretFile)) == "0123456789abcdef-first");

    const Rubric first = loadRubric(
        rubricWith(scratch.path, {{"per_student", true}, {"secret_file", "secret.txt"}}));
    fs::copy_file(secretFile, scratch.path / "moved.txt");
    const Rubric moved =
        loadRubric(rubricWith(scratch.path, {{"per_student", true}, {"secret_file", "moved.txt"}}));
    CHECK(first.hash == moved.hash); // the file's name is not graded
    const std::string before = scenesHash(first, "");
    writeFileAtomically(secretFile, "0123456789abcdef-second\n");
    CHECK(scenesHash(first, "") != before); // a new secret, new scenes for everyone
    const Rubric ranges =
        loadRubric(rubricWith(scratch.path, {{"per_student", true},
                                             {"secret_file", "secret.txt"},
                                             {"furnace", {{"albedo", {0.2, 0.6}}}}}));
    CHECK(ranges.hash != first.hash); // the ranges are graded
}

TEST_CASE("grader rubric describes the variants, the late policy and the regrade setting",
          "[grader]") {
    Rubric rubric = loadRubric(std::string(PATHLAB_GRADER_DIR) + "/rubric.json");
    const std::string plain = rubricText(rubric, "rubric.json", 0);
    CHECK(plain.find("own scenes") == std::string::npos);
    CHECK(plain.find("late:") == std::string::npos);
    rubric.variants = settings("unused");
    rubric.variants.boxScene = "cornell_box_diffuse";
    rubric.late.given = true;
    rubric.late.slipDays = 2;
    rubric.late.penaltyPerDay = 0.1;
    rubric.late.maxPenalty = 0.3;
    rubric.lowerScores = LowerScores::KeepHigher;
    const std::string text = rubricText(rubric, "rubric.json", 0);
    CHECK(text.find("each student's own scenes too (variants): a furnace of albedo in [0.3, 0.8], "
                    "Le in [0.5, 2], maxDepth in [2, 6]") != std::string::npos);
    CHECK(
        text.find("cornell_box_diffuse with each Kd times [0.5, 1] and each Ke times [0.6, 1.3]") !=
        std::string::npos);
    CHECK(text.find("late: 2 slip day(s) per student, then 10% of the total per late day, at most "
                    "30%") != std::string::npos);
    CHECK(text.find("regrades: keep_higher") != std::string::npos);
    // A deadline per lab: the budget is the term's, the penalty a lab's, the labs as they come due.
    rubric.late.labDeadlines = {{"uniform", 1792108740}, {"branching", 1790899140}};
    rubric.late.labExtensionDays = {{"erin", {{"uniform", 2}}}};
    const std::string perLab = rubricText(rubric, "rubric.json", 0);
    CHECK(perLab.find("late: 2 slip day(s) per student for the term, spent as the labs come "
                      "due,\n  then 10% of a late lab's points per late day, at most 30%; "
                      "extensions for 1 student(s)\n  branching due 2026-10-01T23:59:00Z\n  "
                      "uniform due 2026-10-15T23:59:00Z\n") != std::string::npos);
}

TEST_CASE("ids as the grader spells them: an email's @ as _, in the extensions CSV too",
          "[grader]") {
    CHECK(plainId("ada@uni.edu") == "ada_uni.edu");
    CHECK(plainId("Jos\xc3\xa9") == "Jos__");
    CHECK(plainId(".hidden") == "submission.hidden");
    CHECK(plainId("") == "submission");
    ScratchFolder scratch("extensions-ids");
    writeFileAtomically((scratch.path / "extensions.csv").string(), "id,days\nada@uni.edu,3\n");
    const LatePolicy policy =
        readLatePolicy({{"extensions", "extensions.csv"}}, (scratch.path / "rubric.json").string());
    CHECK(policy.extensionDays.count("ada_uni.edu") == 1);
}

TEST_CASE("a student's box has its point light varied too; a furnace's file keeps no public "
          "number",
          "[grader]") {
    ScratchFolder scratch("student-box");
    Rubric rubric = loadRubric(std::string(PATHLAB_GRADER_DIR) + "/rubric.json");
    rubric.variants = settings("unused");
    StudentVariant v = drawStudentVariant(rubric.variants, "0123456789abcdef", "alice");
    studentVariantScenes(rubric, v, (scratch.path / "variant").string(), {}, "", "");
    const std::string furnace = readFile((scratch.path / "variant" / "furnace.ecs").string());
    CHECK(furnace.find("1/(1-a) = 2") == std::string::npos);
    CHECK(furnace.find("-i furnace_furnace.obj") != std::string::npos);

    // The box alone, as studentVariantScenes writes it (its reference needs the solutions).
    std::mt19937_64 engine(v.boxSeed);
    const std::function<double()> random = [&] { return portableUnit(engine); };
    const std::string ecs = readFile(writeVariedScene(publicScenePath("cornell_box_diffuse"),
                                                      (scratch.path / "box").string(), "box",
                                                      random, {0.5, 1.0}, {0.6, 1.3}));
    std::istringstream lines(ecs);
    double intensity = 0;
    for (std::string line; std::getline(lines, line);)
        if (line.rfind("-pointlight", 0) == 0) {
            std::istringstream words(line.substr(11));
            double x, y, z;
            words >> x >> y >> z >> intensity;
        }
    CHECK(intensity >= 0.6 * 150000);
    CHECK(intensity <= 1.3 * 150000);
    CHECK(intensity != 150000);
}
