#include "commands/rescore.h"

#include "checks/expectation.h"
#include "checks/grading_scenes.h"
#include "commands/submission_grading.h"
#include "common/local_time.h"
#include "reports/reports.h"

#include "pathlab/support/input_error.h"

#include <filesystem>
#include <fstream>

namespace pathlab::grader {

namespace fs = std::filesystem;

namespace {

nlohmann::json readJson(const std::string& path) {
    std::ifstream in(path);
    return in ? nlohmann::json::parse(in, nullptr, false) : nlohmann::json();
}

/// The intake as the earlier grading's result.json recorded it.
Intake storedIntake(const nlohmann::json& result) {
    const nlohmann::json i = result.value("intake", nlohmann::json::object());
    Intake intake;
    intake.kind = i.value("kind", "");
    const nlohmann::json taken = i.value("taken", nlohmann::json::object());
    for (const auto& [name, where] : taken.items()) intake.taken[name] = where.get<std::string>();
    intake.problems = i.value("problems", std::vector<std::string>{});
    intake.commit = i.value("commit", "");
    intake.submittedAt = i.value("submitted_at", 0LL);
    intake.timeSource = i.value("time_source", "");
    intake.labTimes = i.value("lab_times", std::map<std::string, long long>{});
    return intake;
}

/// The pictures' reference images, from the public scenes' stored references.
void addReferenceImages(const Rubric& rubric, const std::string& references, LabMeasurement& m) {
    for (LabGrade::Pictures& p : m.pictures) {
        try {
            p.reference =
                loadReference(references, publicScenePath(p.scene), rubric).forLab(m.lab).image;
        } catch (const InputError&) {
            p.reference.clear(); // the page then leaves this picture out
        }
    }
}

} // namespace

Rescore rescoreSubmission(const Rubric& rubric, bool speed, const std::string& references,
                          const Submission& s, const std::string& folder) {
    Rescore rescore;
    const nlohmann::json result = readJson(folder + "/result.json");
    const nlohmann::json stored = readJson(folder + "/measurements.json");
    if (!result.is_object() || !stored.is_object()) return rescore;
    SubmissionOutcome outcome;
    try {
        for (const nlohmann::json& lab : stored.at("labs")) {
            LabMeasurement m = readMeasurement(lab, folder);
            if (speed && !m.speedMeasured && m.ungraded.empty()) return rescore; // must time it
            m.speedMeasured = speed;
            addReferenceImages(rubric, references, m);
            outcome.measurements.push_back(std::move(m));
        }
        outcome.report.notes = stored.value("notes", std::vector<std::string>{});
    } catch (const InputError&) {
        return rescore; // unreadable: graded again instead
    }
    const nlohmann::json under = result.value("graded_under", nlohmann::json::object());
    outcome.id = s.id;
    outcome.rubricHash = rubric.hash;
    outcome.measurementHash = rubric.measurementHash;
    outcome.speedMeasured = speed;
    outcome.scenesHash = under.value("scenes_hash", "");
    outcome.status = result.value("status", "");
    outcome.intake = storedIntake(result);
    outcome.filesHash = result.value("intake", nlohmann::json::object()).value("files_hash", "");
    rescore.fromAttempt = result.value("attempt", 1);
    rescore.before = result.value("score", 0.0);
    rescore.maxBefore = result.value("max_score", 0.0);
    for (const LabMeasurement& m : outcome.measurements)
        outcome.report.labs.push_back(judgeLab(rubric, m));
    outcome.report.notes.push_back(
        "re-scored under the rubric of now from attempt " + std::to_string(rescore.fromAttempt) +
        "'s measurements (only its points or thresholds had changed): nothing was rendered again");
    outcome.how = "re-scored from attempt " + std::to_string(rescore.fromAttempt);
    outcome.attempt = archiveAttempt(folder);
    // The log of the grading whose measurements were judged again stays beside its feedback,
    // for the student it is handed back to, as well as in the archived attempt; it ends with
    // the grade of now, not the one it printed then.
    std::error_code noLog;
    fs::copy_file(folder + "/attempts/" + std::to_string(outcome.attempt - 1) + "/grader.log",
                  folder + "/grader.log", fs::copy_options::overwrite_existing, noLog);
    std::ofstream(folder + "/grader.log", std::ios::app)
        << "\n"
        << localTimeNow() << " " << outcome.report.notes.back() << ". The grade now:\n\n"
        << terminalReport(outcome.report, false);
    writeGrading(outcome, s.path, folder);
    rescore.done = true;
    rescore.after = outcome.report.score();
    rescore.maxAfter = outcome.report.maxScore();
    return rescore;
}

} // namespace pathlab::grader
