#include "commands/batch_estimate.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace pathlab::grader {

namespace fs = std::filesystem;

namespace {

/// What a shard does before its first grading: the hidden scenes' references and the canary
/// (about a minute on the 2-core CI machine, docs/instructor-guide.md).
constexpr double kShardSetupSeconds = 60;

nlohmann::json readJson(const fs::path& path) {
    std::ifstream in(path);
    const nlohmann::json j = in ? nlohmann::json::parse(in, nullptr, false) : nlohmann::json();
    return j.is_object() ? j : nlohmann::json();
}

/// A grading that rendered (not a re-score, which measures nothing and takes no time), timed as
/// `speed` says.
bool renderedAlike(const nlohmann::json& result, bool speed) {
    const nlohmann::json under = result.value("graded_under", nlohmann::json::object());
    return result.value("how", "graded") == "graded" && result.value("seconds", 0.0) > 0 &&
           under.value("speed_measured", false) == speed;
}

} // namespace

std::optional<GradingTime> measuredGradingTime(const std::string& out, bool speed) {
    std::vector<double> seconds;
    std::error_code none;
    // Each submission's gradings that rendered, its earlier attempts' included: after a
    // re-score, the grading now took no time, and the one it judged again is an attempt.
    for (const auto& entry : fs::directory_iterator(fs::path(out) / "submissions", none)) {
        std::vector<fs::path> gradings = {entry.path() / "result.json"};
        for (const auto& attempt : fs::directory_iterator(entry.path() / "attempts", none))
            gradings.push_back(attempt.path() / "result.json");
        for (const fs::path& path : gradings) {
            const nlohmann::json result = readJson(path);
            if (!result.is_null() && renderedAlike(result, speed))
                seconds.push_back(result.value("seconds", 0.0));
        }
    }
    if (!seconds.empty()) {
        std::sort(seconds.begin(), seconds.end());
        return GradingTime{seconds[seconds.size() / 2],
                           "the median of " + std::to_string(seconds.size()) +
                               " earlier grading(s) in this folder, earlier attempts included",
                           ""};
    }
    const nlohmann::json canary = readJson(fs::path(out) / ".canary" / "result.json");
    if (canary.is_null() || canary.value("seconds", 0.0) <= 0) return std::nullopt;
    return GradingTime{canary.value("seconds", 0.0), "the canary's grading of the solutions",
                       std::string("the canary grades alone, with no job beside it") +
                           (speed ? ", and times nothing" : "")};
}

std::string roughDuration(double seconds) {
    const long minutes = std::lround(seconds / 60);
    if (seconds < 90) return std::to_string(std::lround(seconds)) + " s";
    if (minutes < 90) return std::to_string(minutes) + " min";
    return std::to_string(minutes / 60) + " h " + std::to_string(minutes % 60) + " min";
}

double batchSeconds(const GradingTime& time, size_t count, int jobs) {
    return std::ceil(static_cast<double>(count) / std::max(1, jobs)) * time.seconds;
}

std::string batchEstimate(const GradingTime& time, size_t count, int jobs,
                          const SlurmArray& array) {
    // Gradings run `jobs` at a time; each grading's measured wall time already includes its
    // share of the cores with the others, so a batch takes about count / jobs gradings' time.
    const auto wall = [&](double submissions, int atOnce) {
        return std::ceil(submissions / std::max(1, atOnce)) * time.seconds;
    };
    const int nodeJobs = array.cpusPerNode > 2 ? array.cpusPerNode - 1 : 1;
    const double perNode = std::ceil(static_cast<double>(count) / std::max(1, array.nodes));
    std::string text = "estimate: about " + roughDuration(time.seconds) + " per submission here (" +
                       time.from + ")";
    if (!time.lowerBoundBecause.empty())
        text += "; " + time.lowerBoundBecause + ", so read these as lower bounds";
    text += "\nestimate: " + std::to_string(count) + " submission(s) here, " +
            std::to_string(jobs) + " at a time: about " + roughDuration(wall(count, jobs)) +
            "\nestimate: on a Slurm array of " + std::to_string(array.nodes) + " node(s) of " +
            std::to_string(array.cpusPerNode) +
            " cores (PATHLAB_CPUS), as fast as this one: about " +
            roughDuration(kShardSetupSeconds + wall(perNode, nodeJobs)) + " (" +
            std::to_string(static_cast<long>(perNode)) + " a node, " + std::to_string(nodeJobs) +
            " at a time, after a minute of references and canary)";
    return text + "\n";
}

} // namespace pathlab::grader
