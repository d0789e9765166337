#include "checks/rubric.h"

#include "common/content_hash.h"

#include "pathlab/support/input_error.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <fstream>

namespace pathlab::grader {

namespace {

/// The rubric's hashes: of all of it (`about` left out), and of what changes a measurement (not
/// the points, nor the thresholds and the speed verdict's settings, which judge measurements).
void hashRubric(const nlohmann::json& j, Rubric& r) {
    r.hash = ContentHash().add(j.dump()).hex();
    nlohmann::json measured = j;
    measured.erase("points");
    for (const auto& [section, key] :
         {std::pair{"noise", "max_ratio"}, std::pair{"speed", "min_ratio"},
          std::pair{"speed", "alpha"}, std::pair{"speed", "judged_by"},
          std::pair{"hidden_scenes", "gradescope_visibility"}})
        if (measured.contains(section) && measured[section].is_object())
            measured[section].erase(key);
    r.measurementHash = ContentHash().add(measured.dump()).hex();
}

/// The entry of `lab` in the rubric's section `where` ("points", "correctness.spp"): a lab of
/// the lab list the rubric does not mention (one added since it was written) is named.
const nlohmann::json& labEntry(const nlohmann::json& section, const char* where, Lab lab,
                               const std::string& path) {
    const std::string name(labName(lab));
    if (!section.is_object() || !section.contains(name))
        throw InputError(path + ": " + std::string(where) + " has no entry for the lab \"" + name +
                         "\" (lab " + std::to_string(labNumber(lab)) +
                         "); the rubric needs one for every lab of the kit: " + labNames(", "));
    return section.at(name);
}

/// points, parameters, correctness and noise.
void readCorrectnessAndNoise(const nlohmann::json& j, const std::string& path, Rubric& r) {
    for (Lab lab : AllLabs) {
        const auto& p = labEntry(j.at("points"), "points", lab, path);
        LabRubric& l = r.labs[lab];
        l.points = {p.at("correctness"), p.at("noise"), p.at("speed")};
        l.correctnessSpp = labEntry(j.at("correctness").at("spp"), "correctness.spp", lab, path);
    }
    r.maxDepth = j.at("parameters").at("max_depth");
    r.continueProb = j.at("parameters").at("continue_prob");
    const auto& c = j.at("correctness");
    r.alpha = c.at("alpha");
    r.seeds = c.at("seeds");
    r.width = c.at("width");
    r.height = c.at("height");
    r.tiles = c.at("tiles");
    r.scenes = c.at("scenes").get<std::vector<std::string>>();
    r.maxNoiseRatio = j.at("noise").at("max_ratio");
    r.noiseScene = j.at("noise").at("scene");
}

/// speed, with what a rubric of before the timed runs were the correctness renders still says.
void readSpeed(const nlohmann::json& j, const std::string& path, Rubric& r) {
    const auto& s = j.at("speed");
    r.minSpeedRatio = s.at("min_ratio");
    r.speedRuns = s.at("runs");
    r.speedScene = s.at("scene");
    r.speedAlpha = s.value("alpha", r.speedAlpha);
    // Their sizes no longer say anything, and are read as what they were.
    for (const char* gone : {"width", "height", "spp"})
        if (s.contains(gone))
            std::fprintf(stderr,
                         "%s: note: speed.%s is no longer used: the timed runs are the "
                         "correctness renders of speed.scene\n",
                         path.c_str(), gone);
    for (Lab lab : AllLabs) {
        const std::string measure = s.value("judged_by", nlohmann::json::object())
                                        .value(std::string(labName(lab)), "samples_per_second");
        if (measure != "samples_per_second" && measure != "efficiency")
            throw InputError(path + ": speed.judged_by." + std::string(labName(lab)) + " is '" +
                             measure + "'; it must be samples_per_second or efficiency");
        r.labs[lab].speedJudgedBy =
            measure == "efficiency" ? SpeedMeasure::Efficiency : SpeedMeasure::SamplesPerSecond;
    }
}

/// parameter_check and hidden_scenes, optional as judged_by: a rubric written before they
/// existed grades as it did, plus the default parameter check; and the limits.
void readOptionalSectionsAndLimits(const nlohmann::json& j, const std::string& path, Rubric& r) {
    if (j.contains("parameter_check")) {
        const auto& p = j.at("parameter_check");
        r.parameterCheck = {p.at("scene"), p.at("max_depth"), p.at("continue_prob")};
    }
    if (j.contains("hidden_scenes")) {
        r.hiddenScenesVisibility =
            j.at("hidden_scenes").value("gradescope_visibility", r.hiddenScenesVisibility);
        r.sceneVariants = j.at("hidden_scenes").value("variants", r.sceneVariants);
        if (r.sceneVariants < 0 || r.sceneVariants > 10)
            throw InputError(path + ": hidden_scenes.variants must be 0 to 10");
        const auto& v = r.hiddenScenesVisibility;
        if (v != "visible" && v != "hidden" && v != "after_due_date" && v != "after_published")
            throw InputError(path + ": hidden_scenes.gradescope_visibility is '" + v +
                             "'; it must be "
                             "visible, hidden, after_due_date or after_published");
    }
    r.secondsPerRun = j.at("limits").at("seconds_per_run");
    r.memoryBytes = static_cast<long long>(j.at("limits").at("memory_mb").get<double>()) << 20;
}

/// regrades.lower_scores, optional: a rubric without it leaves the choice to be made.
LowerScores readLowerScores(const nlohmann::json& j, const std::string& path) {
    if (!j.contains("regrades")) return LowerScores::Undecided;
    const std::string choice = j.at("regrades").value("lower_scores", "");
    if (choice == "replace") return LowerScores::Replace;
    if (choice == "keep_higher") return LowerScores::KeepHigher;
    throw InputError(path + ": regrades.lower_scores is '" + choice +
                     "'; it must be replace (a regrade's lower total counts) or keep_higher "
                     "(the higher earlier total of the same files counts)");
}

/// gradescope.leaderboard, optional: results.json without a leaderboard unless it is true.
bool readGradescopeLeaderboard(const nlohmann::json& j, const std::string& path) {
    if (!j.contains("gradescope")) return false;
    const auto& g = j.at("gradescope");
    if (!g.is_object() || !g.contains("leaderboard") || !g.at("leaderboard").is_boolean())
        throw InputError(path + ": gradescope.leaderboard must be true or false");
    return g.at("leaderboard").get<bool>();
}

/// What no single value shows: values that must agree with each other.
void requireConsistent(const Rubric& r, const std::string& path) {
    if (r.seeds < 2 || r.width < r.tiles || r.height < r.tiles || r.tiles < 1 ||
        !(r.continueProb > 0 && r.continueProb < 1) || r.maxDepth < 0 || r.speedRuns < 1)
        throw InputError(path + ": seeds must be >= 2, tiles fit the image, 0 < continue_prob < 1");
    if (std::find(r.scenes.begin(), r.scenes.end(), r.speedScene) == r.scenes.end())
        throw InputError(path + ": speed.scene '" + r.speedScene +
                         "' must be one of correctness.scenes: its correctness renders are the "
                         "ones timed");
    if (!(r.speedAlpha > 0 && r.speedAlpha < 1))
        throw InputError(path + ": speed.alpha must lie between 0 and 1");
    const ParameterCheck& second = r.parameterCheck;
    if (!(second.continueProb > 0 && second.continueProb < 1) || second.maxDepth < 0 ||
        second.maxDepth == r.maxDepth || second.continueProb == r.continueProb)
        throw InputError(path + ": parameter_check needs 0 < continue_prob < 1, max_depth >= 0, "
                                "both other than the parameters'");
}

} // namespace

const char* lowerScoresName(LowerScores choice) {
    return choice == LowerScores::Replace      ? "replace"
           : choice == LowerScores::KeepHigher ? "keep_higher"
                                               : "";
}

Rubric loadRubric(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw InputError(path + ": cannot open the rubric");
    Rubric r;
    try {
        nlohmann::json j = nlohmann::json::parse(in);
        j.erase("about");
        r.lowerScores = readLowerScores(j, path);
        r.late = readLatePolicy(j.contains("late") ? j.at("late") : nlohmann::json(), path);
        r.variants =
            readVariantSettings(j.contains("variants") ? j.at("variants") : nlohmann::json(), path);
        r.gradescopeLeaderboard = readGradescopeLeaderboard(j, path);
        j.erase("regrades"); // which total the gradebook shows: no result goes stale for it
        j.erase("late");
        j.erase("gradescope");
        // The secret's file may move, and a release's rubric leaves it out: its text is in the
        // scenes' hash instead (grading_scenes.h).
        if (j.contains("variants") && j["variants"].is_object()) j["variants"].erase("secret_file");
        hashRubric(j, r);
        readCorrectnessAndNoise(j, path, r);
        readSpeed(j, path, r);
        readOptionalSectionsAndLimits(j, path, r);
    } catch (const nlohmann::json::exception& e) {
        throw InputError(path + ": " + e.what());
    }
    requireConsistent(r, path);
    return r;
}

} // namespace pathlab::grader
