#include "checks/lab_measurement.h"

#include "checks/noise_check.h"
#include "checks/speed_check.h"

#include "pathlab/images/image_io.h"
#include "pathlab/support/input_error.h"

#include <filesystem>

namespace pathlab::grader {

namespace {

namespace fs = std::filesystem;

nlohmann::json checkJson(const CheckResult& c) {
    return {{"kind", c.name()},           {"passed", c.passed},
            {"summary", c.summary},       {"details", c.details},
            {"diagnosis", c.diagnosis},   {"hidden_scenes", c.hiddenSceneDetails},
            {"graded_here", c.gradedHere}};
}

CheckResult readCheck(const nlohmann::json& j) {
    CheckResult c;
    c.kind = CheckKind::Correctness;
    c.passed = j.at("passed");
    c.summary = j.at("summary");
    c.details = j.at("details").get<std::vector<std::string>>();
    c.diagnosis = j.at("diagnosis");
    c.hiddenSceneDetails = j.at("hidden_scenes").get<std::vector<std::string>>();
    c.gradedHere = j.at("graded_here");
    return c;
}

nlohmann::json raysJson(const RayCounters& rays) {
    return {{"intersect", rays.intersect}, {"occluded", rays.occluded}};
}

RayCounters readRays(const nlohmann::json& j) { return {j.at("intersect"), j.at("occluded")}; }

/// Where a picture's lab image is kept: pictures/LAB.SCENE.pfm in the submission's folder.
std::string pictureFile(const std::string& folder, Lab lab, const std::string& scene) {
    return folder + "/pictures/" + std::string(labName(lab)) + "." + scene + ".pfm";
}

} // namespace

LabGrade ungradedLab(const Rubric& rubric, Lab lab, bool measureSpeed, const std::string& reason,
                     const std::vector<std::string>& details) {
    LabGrade grade;
    grade.lab = lab;
    for (CheckKind kind : AllChecks) {
        if (kind == CheckKind::Speed && !measureSpeed) continue;
        CheckResult check;
        check.kind = kind;
        check.maxScore = rubric.forLab(lab).points.of(kind);
        check.summary = reason;
        check.diagnosis = reason;
        if (kind == CheckKind::Correctness) check.details = details;
        grade.checks.push_back(check);
    }
    return grade;
}

LabGrade judgeLab(const Rubric& rubric, const LabMeasurement& m) {
    if (!m.ungraded.empty())
        return ungradedLab(rubric, m.lab, m.speedMeasured, m.ungraded, m.ungradedDetails);
    LabGrade grade;
    grade.lab = m.lab;
    CheckResult correctness = m.correctness;
    correctness.kind = CheckKind::Correctness;
    correctness.maxScore = rubric.forLab(m.lab).points.correctness;
    correctness.score = correctness.passed ? correctness.maxScore : 0;
    grade.checks.push_back(correctness);
    grade.pictures = m.pictures;
    grade.rendersFinished = m.rendersFinished;
    const NoiseOutcome noise = judgeNoise(rubric, m.lab, correctness.passed, m.noise);
    grade.checks.push_back(noise.check);
    grade.studentVariance = noise.variances.student;
    grade.solutionVariance = noise.variances.solution;
    if (!m.speedMeasured) return grade;
    const SpeedOutcome speed =
        judgeTimedRuns(rubric, m.lab, correctness.passed, noise.variances, m.speed);
    grade.checks.push_back(speed.check);
    static_cast<SpeedFigures&>(grade) = speed;
    return grade;
}

nlohmann::json measurementJson(const LabMeasurement& m, const std::string& folder) {
    nlohmann::json pictures = nlohmann::json::array();
    for (const LabGrade::Pictures& p : m.pictures) {
        const std::string file = pictureFile(folder, m.lab, p.scene);
        fs::create_directories(fs::path(file).parent_path());
        writeImage(file, p.width, p.height, p.student);
        pictures.push_back({{"scene", p.scene},
                            {"width", p.width},
                            {"height", p.height},
                            {"tiles_per_side", p.tilesPerSide},
                            {"region_t", p.regionT},
                            {"region_p", p.regionP}});
    }
    const TimedMeasurement& t = m.speed;
    return {{"lab", labName(m.lab)},
            {"seconds",
             {{"correctness", m.seconds.correctness},
              {"race_check", m.seconds.race},
              {"speed", m.seconds.speed}}},
            {"ungraded", m.ungraded},
            {"ungraded_details", m.ungradedDetails},
            {"correctness", checkJson(m.correctness)},
            {"renders_finished", m.rendersFinished},
            {"noise",
             {{"student", m.noise.student},
              {"solution", m.noise.solution},
              {"scene", m.noise.scene},
              {"strategies", strategyTilesJson(m.noise.strategies)}}},
            {"speed_measured", m.speedMeasured},
            {"speed",
             {{"not_timed", t.notTimed},
              {"not_timed_diagnosis", t.notTimedDiagnosis},
              {"student", t.student},
              {"solution", t.solution},
              {"student_wall_seconds", t.studentWall},
              {"solution_wall_seconds", t.solutionWall},
              {"student_rays", raysJson(t.studentRays)},
              {"solution_rays", raysJson(t.solutionRays)},
              {"student_samples", t.studentSamples},
              {"solution_samples", t.solutionSamples},
              {"cpu_seconds", t.cpuSeconds},
              {"wall_seconds", t.wallSeconds},
              {"timing_cores", t.timingCores},
              {"images_differ", t.imagesDiffer}}},
            {"pictures", pictures}};
}

LabMeasurement readMeasurement(const nlohmann::json& j, const std::string& folder) {
    LabMeasurement m;
    try {
        const auto lab = labFromName(j.at("lab").get<std::string>());
        if (!lab) throw InputError("no such lab '" + j.at("lab").get<std::string>() + "'");
        m.lab = *lab;
        if (const nlohmann::json seconds = j.value("seconds", nlohmann::json());
            seconds.is_object())
            m.seconds = {seconds.value("correctness", 0.0), seconds.value("race_check", 0.0),
                         seconds.value("speed", 0.0)};
        m.ungraded = j.at("ungraded");
        m.ungradedDetails = j.at("ungraded_details").get<std::vector<std::string>>();
        m.correctness = readCheck(j.at("correctness"));
        m.rendersFinished = j.at("renders_finished");
        const nlohmann::json& n = j.at("noise");
        m.noise = {n.at("student"), n.at("solution"), n.at("scene"), {}};
        // Measurements stored before lab 6 have no strategies.
        if (n.contains("strategies")) m.noise.strategies = readStrategyTiles(n.at("strategies"));
        m.speedMeasured = j.at("speed_measured");
        const nlohmann::json& s = j.at("speed");
        TimedMeasurement& t = m.speed;
        t.notTimed = s.at("not_timed");
        t.notTimedDiagnosis = s.at("not_timed_diagnosis");
        t.student = s.at("student").get<std::vector<double>>();
        t.solution = s.at("solution").get<std::vector<double>>();
        t.studentWall = s.value("student_wall_seconds", std::vector<double>{});
        t.solutionWall = s.value("solution_wall_seconds", std::vector<double>{});
        t.studentRays = readRays(s.at("student_rays"));
        t.solutionRays = readRays(s.at("solution_rays"));
        t.studentSamples = s.at("student_samples");
        t.solutionSamples = s.at("solution_samples");
        t.cpuSeconds = s.at("cpu_seconds");
        t.wallSeconds = s.at("wall_seconds");
        t.timingCores = s.at("timing_cores");
        t.imagesDiffer = s.at("images_differ");
        for (const nlohmann::json& p : j.at("pictures")) {
            LabGrade::Pictures picture;
            picture.scene = p.at("scene");
            picture.width = p.at("width");
            picture.height = p.at("height");
            picture.tilesPerSide = p.at("tiles_per_side");
            picture.regionT = p.at("region_t").get<std::vector<double>>();
            picture.regionP = p.at("region_p").get<std::vector<double>>();
            picture.student = readImage(pictureFile(folder, m.lab, picture.scene)).rgb;
            m.pictures.push_back(std::move(picture));
        }
    } catch (const nlohmann::json::exception& e) {
        throw InputError(folder + "/measurements.json: " + e.what());
    }
    return m;
}

} // namespace pathlab::grader
