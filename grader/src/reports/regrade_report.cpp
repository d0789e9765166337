#include "reports/regrade_report.h"

#include "reports/reports.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <utility>

namespace pathlab::grader {

namespace fs = std::filesystem;

namespace {

nlohmann::json readResult(const std::string& path) {
    std::ifstream in(path);
    const nlohmann::json j = in ? nlohmann::json::parse(in, nullptr, false) : nlohmann::json();
    return j.is_object() ? j : nlohmann::json();
}

std::string number(double value) {
    std::ostringstream out;
    out << std::round(100 * value) / 100;
    return out.str();
}

std::string scoreText(const std::optional<double>& score) {
    return score ? number(*score) : std::string("not checked");
}

const nlohmann::json& objectOr(const nlohmann::json& j, const char* key) {
    static const nlohmann::json empty = nlohmann::json::object();
    return j.is_object() && j.contains(key) && j.at(key).is_object() ? j.at(key) : empty;
}

/// Whether two gradings took in the same files: a regrade, not a resubmission.
bool sameFiles(const nlohmann::json& a, const nlohmann::json& b) {
    const nlohmann::json& x = objectOr(a, "intake");
    const nlohmann::json& y = objectOr(b, "intake");
    return x.value("files_hash", "") == y.value("files_hash", "") &&
           x.value("commit", "") == y.value("commit", "");
}

/// Why `now` was graded again after `before`, from what each was graded under.
std::vector<std::string> reasonsFor(const nlohmann::json& before, const nlohmann::json& now) {
    std::vector<std::string> reasons;
    const nlohmann::json& was = objectOr(before, "graded_under");
    const nlohmann::json& is = objectOr(now, "graded_under");
    const auto differs = [&](const char* key) { return was.value(key, "") != is.value(key, ""); };
    if (!sameFiles(before, now)) reasons.push_back("the submission's files changed");
    if (differs("rubric_hash"))
        reasons.push_back(differs("measurement_hash")
                              ? "the rubric changed what is measured (seeds, sizes, scenes, "
                                "parameters or limits)"
                              : "the rubric's points or thresholds changed");
    if (differs("scenes_hash"))
        reasons.push_back("the scenes changed (public, hidden or variants)");
    if (differs("kit_version"))
        reasons.push_back("the kit changed (" + was.value("kit_version", "?") + " -> " +
                          is.value("kit_version", "?") + ")");
    if (was.value("speed_measured", false) != is.value("speed_measured", false))
        reasons.push_back(is.value("speed_measured", false) ? "speed is measured now"
                                                            : "speed is no longer measured");
    if (reasons.empty())
        reasons.push_back("graded again as asked (--force or --only); nothing it is graded "
                          "under changed");
    return reasons;
}

std::optional<double> checkScore(const nlohmann::json& result, const std::string& lab,
                                 const std::string& check) {
    const nlohmann::json& checks =
        objectOr(objectOr(objectOr(result, "labs"), lab.c_str()), "checks");
    if (!checks.contains(check) || !checks.at(check).is_object()) return std::nullopt;
    return checks.at(check).value("score", 0.0);
}

/// The checks whose points differ between two gradings, in the order of the later one's labs
/// and checks, then any only the earlier one made.
std::vector<ScoreChange> changedChecks(const nlohmann::json& before, const nlohmann::json& now) {
    std::vector<std::pair<std::string, std::string>> keys;
    std::set<std::pair<std::string, std::string>> seen;
    for (const nlohmann::json* result : {&now, &before})
        for (const auto& [lab, labResult] : objectOr(*result, "labs").items())
            for (const auto& [check, ignored] : objectOr(labResult, "checks").items())
                if (seen.insert({lab, check}).second) keys.push_back({lab, check});
    std::vector<ScoreChange> changes;
    for (const auto& [lab, check] : keys) {
        const std::optional<double> was = checkScore(before, lab, check);
        const std::optional<double> is = checkScore(now, lab, check);
        if (was != is) changes.push_back({lab, check, was, is});
    }
    return changes;
}

std::string joined(const std::vector<std::string>& parts, const char* separator) {
    std::string text;
    for (const std::string& part : parts) text += (text.empty() ? "" : separator) + part;
    return text;
}

} // namespace

std::optional<RegradeComparison> compareWithAttemptBefore(const std::string& id,
                                                          const std::string& folder,
                                                          const nlohmann::json& result) {
    const int attempt = result.value("attempt", 1);
    if (attempt < 2) return std::nullopt;
    const nlohmann::json before =
        readResult(folder + "/attempts/" + std::to_string(attempt - 1) + "/result.json");
    if (before.is_null()) return std::nullopt;
    RegradeComparison c;
    c.id = id;
    c.fromAttempt = attempt - 1;
    c.toAttempt = attempt;
    c.before = before.value("score", 0.0);
    c.maxBefore = before.value("max_score", 0.0);
    c.after = result.value("score", 0.0);
    c.maxAfter = result.value("max_score", 0.0);
    c.reasons = reasonsFor(before, result);
    c.changes = changedChecks(before, result);
    c.resubmitted = !sameFiles(before, result);
    return c;
}

std::optional<EarlierTotal> higherEarlierTotal(const std::string& folder,
                                               const nlohmann::json& result) {
    std::optional<EarlierTotal> best;
    const double now = result.value("score", 0.0);
    const double max = result.value("max_score", 0.0);
    std::error_code none;
    for (const auto& entry : fs::directory_iterator(folder + "/attempts", none)) {
        const nlohmann::json earlier = readResult(entry.path().string() + "/result.json");
        if (earlier.is_null() || earlier.value("max_score", -1.0) != max ||
            !sameFiles(earlier, result))
            continue;
        const double score = earlier.value("score", 0.0);
        if (score > now && (!best || score > best->score))
            best = EarlierTotal{earlier.value("attempt", 0), score};
    }
    return best;
}

std::string regradeLine(const RegradeComparison& c) {
    std::string line = c.id + ": attempt " + std::to_string(c.fromAttempt) + " -> " +
                       std::to_string(c.toAttempt) + " (" + joined(c.reasons, "; ") +
                       "): " + number(c.before) + " / " + number(c.maxBefore) + " -> " +
                       number(c.after) + " / " + number(c.maxAfter);
    if (c.changes.empty()) return line + "; no check's points changed";
    std::vector<std::string> parts;
    for (const ScoreChange& change : c.changes)
        parts.push_back(change.lab + " " + change.check + " " + scoreText(change.before) + " -> " +
                        scoreText(change.after));
    return line + "; " + joined(parts, ", ");
}

std::string regradesCsv(const std::vector<RegradeComparison>& comparisons) {
    std::string text = "id,from_attempt,to_attempt,lab,check,before,after,max_before,max_after,"
                       "reason\n";
    for (const RegradeComparison& c : comparisons) {
        const std::string row = csvField(c.id) + "," + std::to_string(c.fromAttempt) + "," +
                                std::to_string(c.toAttempt) + ",";
        const std::string reason = csvField(joined(c.reasons, "; "));
        text += row + "total,total," + number(c.before) + "," + number(c.after) + "," +
                number(c.maxBefore) + "," + number(c.maxAfter) + "," + reason + "\n";
        for (const ScoreChange& change : c.changes)
            text += row + csvField(change.lab) + "," + csvField(change.check) + "," +
                    (change.before ? number(*change.before) : "") + "," +
                    (change.after ? number(*change.after) : "") + ",,," + reason + "\n";
    }
    return text;
}

std::string regradesHtml(const std::vector<RegradeComparison>& comparisons) {
    if (comparisons.empty()) return "<p>No submission has been graded more than once.</p>\n";
    std::ostringstream html;
    html << "<p>Each submission's last grading against the one before it (regrades.csv has the "
            "same, a row per check).</p>\n<table><tr><th>id</th><th>attempts</th><th>total</th>"
            "<th>why graded again</th><th>checks whose points changed</th></tr>\n";
    for (const RegradeComparison& c : comparisons) {
        std::vector<std::string> parts;
        for (const ScoreChange& change : c.changes)
            parts.push_back(escapeXml(change.lab + " " + change.check + ": ") +
                            scoreText(change.before) + " &rarr; " + scoreText(change.after));
        html << "<tr><td>" << escapeXml(c.id) << "</td><td>" << c.fromAttempt << " &rarr; "
             << c.toAttempt << "</td><td>" << number(c.before) << " / " << number(c.maxBefore)
             << " &rarr; " << number(c.after) << " / " << number(c.maxAfter) << "</td><td>"
             << escapeXml(joined(c.reasons, "; ")) << "</td><td>"
             << (parts.empty() ? "none" : joined(parts, "<br>")) << "</td></tr>\n";
    }
    html << "</table>\n";
    return html.str();
}

} // namespace pathlab::grader
