#include "commands/batch_canary.h"

#include "commands/batch_jobs.h"
#include "commands/rescore.h"

#include "pathlab/support/input_error.h"
#include "pathlab/support/whole_file.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace pathlab::grader {

namespace fs = std::filesystem;

namespace {

/// What the canary is judged by: the grading now, without speed.
GradingNow canaryGrading(GradingNow now, const Rubric& rubric) {
    now.measuresSpeed = false;
    now.maxScore = maxScoreNow(rubric, false);
    return now;
}

} // namespace

double maxScoreNow(const Rubric& rubric, bool speed) {
    double max = 0;
    for (Lab lab : AllLabs) {
        const LabPoints& p = rubric.forLab(lab).points;
        max += p.correctness + p.noise + (speed ? p.speed : 0);
    }
    return max;
}

void runCanary(const std::vector<std::string>& childBase, const std::string& solutions,
               const std::string& out, const GradingNow& now, const Rubric& rubric,
               const std::string& references, const std::function<void()>& prepare,
               std::ofstream& log) {
    // `childBase` is the gradings' command line once `prepare` has run.
    const std::string folder = out + "/.canary";
    const std::string fingerprint = now.rubricHash + " " + now.scenesHash + " " + PATHLAB_VERSION;
    {
        std::ifstream passed(folder + "/passed");
        std::string previous;
        if (passed && std::getline(passed, previous) && previous == fingerprint) return;
    }
    const auto start = std::chrono::steady_clock::now();
    std::string how = "graded";
    std::ifstream stored(folder + "/result.json");
    const nlohmann::json earlier =
        stored ? nlohmann::json::parse(stored, nullptr, false) : nlohmann::json();
    stored.close();
    // Only a canary that passed is judged again: one that failed measured against what was wrong.
    if (fs::exists(folder + "/passed") && earlier.is_object() &&
        regradeNeeded(earlier, canaryGrading(now, rubric)) == Regrade::Rescore &&
        rescoreSubmission(rubric, false, references, {solutions, "canary"}, folder).done) {
        how = "re-scored";
    } else {
        prepare();
        std::fprintf(stderr, "canary: grading the reference solutions on every scene ...\n");
        fs::remove_all(folder);
        fs::create_directories(folder);
        std::vector<std::string> argv = childBase;
        argv.insert(argv.end(), {solutions, "--out", folder, "--no-speed"});
        Job job = startJob(argv, {solutions, "canary"}, folder + "/grader.log");
        job.child.wait();
    }
    std::ifstream in(folder + "/result.json");
    const nlohmann::json result = in ? nlohmann::json::parse(in, nullptr, false) : nlohmann::json();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!result.is_object())
        throw InputError("canary: the reference solutions could not be graded (see " + folder +
                         "/grader.log); nothing was graded");
    const double score = result.value("score", 0.0), max = result.value("max_score", 0.0);
    log << timestamp() << " canary: reference solutions " << score << " / " << max << ", " << how
        << ", " << std::lround(seconds) << " s\n"
        << std::flush;
    if (score != max || max == 0) {
        std::string why;
        for (const auto& d : result.value("diagnoses", nlohmann::json::array()))
            why += "\n  " + d.value("lab", "") + " " + d.value("check", "") + ": " +
                   d.value("diagnosis", "");
        char points[64];
        std::snprintf(points, sizeof points, "%g / %g", score, max);
        log << timestamp() << " canary: refused the batch: nothing was graded" << why << "\n"
            << std::flush;
        throw InputError(
            "canary: the reference solutions score " + std::string(points) +
            " on this grading, so its references, scenes or rubric are wrong; nothing was "
            "graded. What failed:" +
            why +
            "\n  A threshold the reference solutions fail (the noise check's max_ratio, the "
            "speed check's min_ratio) is tighter than their own spread from one grading to the "
            "next: loosen it in the rubric (docs/instructor-guide.md, The canary)."
            "\n  (details: " +
            folder + "/index.html)");
    }
    writeFileAtomically(folder + "/passed", fingerprint + "\n");
}

} // namespace pathlab::grader
