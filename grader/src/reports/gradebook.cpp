#include "reports/gradebook.h"

#include "checks/check_kind.h"
#include "reports/class_history.h"
#include "reports/histogram_svg.h"
#include "reports/late_cost.h"
#include "reports/similarity_clusters.h"
#include "reports/page_style.h"
#include "reports/reports.h"
#include "reports/submission_time.h"

#include "pathlab/render/lab_registry.h"
#include "pathlab/render/render_stats.h"
#include "pathlab/support/whole_file.h"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

namespace pathlab::grader {

namespace {

std::string number(double value) {
    std::ostringstream out;
    out << value;
    return out.str();
}

/// "yes", "no", "unknown" (handed in with no time known: --times gives it), or "" where no
/// deadline applies; an extension moves the deadline.
std::string lateness(const GradebookEntry& e, const GradingNow& now) {
    const std::optional<LateCost> late = lateCostOf(e, now);
    if (!late) return "";
    if (late->daysLate > 0) return "yes";
    return late->timeUnknown ? "unknown" : "no";
}

/// The total after the late policy's penalty: what the LMS gets.
std::optional<double> finalTotal(const GradebookEntry& e, const GradingNow& now) {
    const std::optional<double> total = countedTotal(e, now);
    const std::optional<LateCost> late = lateCostOf(e, now);
    if (!total || !late || !now.late.given) return total;
    return std::round(100 * *total * (1 - late->penalty)) / 100;
}

/// A regrade lowered the total, and the rubric has not said whether that counts: the LMS keeps
/// the grade it has.
bool loweredUndecided(const GradebookEntry& e, const GradingNow& now) {
    return e.higherEarlier && now.lowerScores == LowerScores::Undecided;
}

/// What the status adds for a total a regrade lowered.
std::string loweredNote(const GradebookEntry& e, const GradingNow& now) {
    if (!e.higherEarlier) return "";
    const std::string earlier = number(e.higherEarlier->score) + " (attempt " +
                                std::to_string(e.higherEarlier->attempt) + ")";
    const std::string graded = number(e.result.value("score", 0.0));
    switch (now.lowerScores) {
    case LowerScores::Replace:
        return "; a regrade lowered the total from " + earlier + " to " + graded +
               " (regrades.lower_scores: replace)";
    case LowerScores::KeepHigher:
        return "; kept the total " + earlier + ", higher than this grading's " + graded +
               " (regrades.lower_scores: keep_higher)";
    case LowerScores::Undecided: break;
    }
    return "; a regrade lowered the total from " + earlier + " to " + graded +
           ": withheld from lms.csv until the rubric's regrades.lower_scores says replace or "
           "keep_higher";
}

std::string statusOf(const GradebookEntry& e, const GradingNow& now) {
    if (e.pending) return "pending";
    if (e.result.is_null()) return "not graded: " + e.problem;
    std::string status = e.result.value("status", "") + loweredNote(e, now);
    if (const std::string stale = staleness(e.result, now); !stale.empty()) {
        status = "stale: " + stale +
                 "; grade it again: the batch run again without --keep-stale, or with --only " +
                 e.id + " (" + status + ")";
    }
    return status;
}

/// Labs 1 to 4, whose scores the first gradebooks had between the id and the total.
bool inFirstGradebooks(Lab lab) { return labNumber(lab) <= 4; }

/// The columns of the first gradebooks first, in their order (scripts read them by position:
/// id, labs 1 to 4, total, max_total, status), then the later labs' scores, a column per lab and
/// check, and what a registrar asks.
std::string csv(const std::vector<GradebookEntry>& entries, const GradingNow& now) {
    std::string text = "id";
    for (Lab lab : AllLabs)
        if (inFirstGradebooks(lab)) text += "," + std::string(labName(lab));
    text += ",total,max_total,status";
    for (Lab lab : AllLabs)
        if (!inFirstGradebooks(lab)) text += "," + std::string(labName(lab));
    for (Lab lab : AllLabs)
        for (CheckKind check : AllChecks)
            text += "," + std::string(labName(lab)) + "_" + std::string(checkName(check));
    text += ",missing_labs,submitted_at,time_source,late,commit,files_hash,rubric_hash,attempt,"
            "graded_total,late_days,slip_days_used,late_penalty,final_total,late_labs\n";
    for (const GradebookEntry& e : entries) {
        const std::optional<double> total = countedTotal(e, now);
        const nlohmann::json labs =
            total ? e.result.value("labs", nlohmann::json::object()) : nlohmann::json::object();
        auto labResult = [&](Lab lab) {
            return labs.value(std::string(labName(lab)), nlohmann::json::object());
        };
        const auto labScore = [&](Lab lab) {
            return "," + (total ? number(labResult(lab).value("score", 0.0)) : "");
        };
        text += csvField(e.id);
        for (Lab lab : AllLabs)
            if (inFirstGradebooks(lab)) text += labScore(lab);
        text += "," + (total ? number(*total) : "") + "," + number(now.maxScore) + "," +
                csvField(statusOf(e, now));
        for (Lab lab : AllLabs)
            if (!inFirstGradebooks(lab)) text += labScore(lab);
        for (Lab lab : AllLabs)
            for (CheckKind check : AllChecks) {
                const nlohmann::json c =
                    labResult(lab)
                        .value("checks", nlohmann::json::object())
                        .value(std::string(checkName(check)), nlohmann::json());
                text += "," + (c.is_object() && c.value("graded_here", true)
                                   ? number(c.value("score", 0.0))
                                   : "");
            }
        const nlohmann::json intake = e.result.is_null()
                                          ? nlohmann::json::object()
                                          : e.result.value("intake", nlohmann::json::object());
        std::string missing;
        if (!e.result.is_null())
            for (const auto& lab : e.result.value("missing_labs", nlohmann::json::array()))
                missing += (missing.empty() ? "" : " ") + lab.get<std::string>();
        const auto [at, source] = submittedAt(e, now);
        const nlohmann::json under = e.result.is_null()
                                         ? nlohmann::json::object()
                                         : e.result.value("graded_under", nlohmann::json::object());
        text += "," + csvField(missing) + "," + (at ? isoTime(at) : "") + "," + csvField(source) +
                "," + lateness(e, now) + "," + csvField(intake.value("commit", "")) + "," +
                csvField(intake.value("files_hash", "")) + "," +
                csvField(under.value("rubric_hash", "")) + "," +
                (e.result.is_null() ? "" : number(e.result.value("attempt", 1))) + "," +
                (total ? number(e.result.value("score", 0.0)) : "");
        const std::optional<LateCost> late = lateCostOf(e, now);
        const std::optional<double> finalScore = finalTotal(e, now);
        text += "," + (late ? number(late->daysLate) : "") + "," +
                (late && now.late.given ? number(late->slipDaysUsed) : "") + "," +
                (late && now.late.given ? number(std::round(1000 * late->penalty) / 1000) : "") +
                "," + (finalScore ? number(*finalScore) : "") + "," +
                csvField(late ? late->labs : "") + "\n";
    }
    return text;
}

/// For an LMS's grade import (Canvas, Moodle): a row per submission graded under the grading now;
/// the id stands for the student's login (name submissions after it).
std::string lmsCsv(const std::vector<GradebookEntry>& entries, const GradingNow& now) {
    std::string text = "Student,SIS Login ID,PathLab (" + number(now.maxScore) + " points)\n";
    // A total the grading now does not give (pending: being graded again; stale: graded under
    // another rubric or scenes) is withheld: the import keeps what it had for that student.
    for (const GradebookEntry& e : entries)
        if (const std::optional<double> total = finalTotal(e, now);
            total && !e.pending && staleness(e.result, now).empty() && !loweredUndecided(e, now))
            text += csvField(e.id) + "," + csvField(e.id) + "," + number(*total) + "\n";
    return text;
}

/// A bar chart of the totals in tenths of the maximum, as inline SVG; of one lab's scores in
/// tenths of its maximum with `lab` (a submission without that lab counts as 0).
std::string histogram(const std::vector<GradebookEntry>& entries,
                      std::optional<Lab> lab = std::nullopt) {
    std::array<int, 10> bins{};
    for (const GradebookEntry& e : entries) {
        if (e.result.is_null()) continue;
        const nlohmann::json scored =
            lab ? e.result.value("labs", nlohmann::json::object())
                      .value(std::string(labName(*lab)), nlohmann::json::object())
                : e.result;
        const double max = scored.value("max_score", 0.0);
        const double fraction = max > 0 ? scored.value("score", 0.0) / max : 0;
        ++bins[std::clamp(static_cast<int>(std::floor(fraction * 10)), 0, 9)];
    }
    return histogramSvg(bins, lab ? std::string(labName(*lab)) + " score, % of its maximum"
                                  : std::string("total score, % of the maximum"));
}

/// A histogram per lab, side by side where the page is wide enough.
std::string labHistograms(const std::vector<GradebookEntry>& entries) {
    std::string html = "<div style=\"display:flex;flex-wrap:wrap;gap:1em\">\n";
    for (Lab lab : AllLabs) html += "<div>" + histogram(entries, lab) + "</div>\n";
    return html + "</div>\n";
}

/// The pairs of submissions whose files of a lab are alike, grouped into clusters: a hint to
/// look, never a verdict.
std::string similarityTable(const std::optional<std::vector<SimilarLabs>>& pairs) {
    if (!pairs) return "<p>Compared once every submission is graded.</p>\n";
    if (pairs->empty())
        return "<p>No two submissions' files of a lab are alike beyond the threshold.</p>\n";
    return "<p>Files of the same lab whose normalised token streams (names, numbers and layout "
           "ignored, the stub's code left out) are alike, grouped: a cluster is the submissions "
           "joined by a chain of alike files. A hint to read them side by side, never a grade. "
           "\"reference solutions\" is the kit's own; similarity.csv has every pair.</p>\n" +
           clustersHtml(similarClusters(*pairs));
}

/// similarity.csv: every pair, most alike first.
std::string similarityCsv(const std::vector<SimilarLabs>& pairs) {
    std::string text = "lab,first,second,similarity\n";
    for (const SimilarLabs& p : pairs)
        text += csvField(p.lab) + "," + csvField(p.first) + "," + csvField(p.second) + "," +
                number(std::round(1000 * p.similarity) / 1000) + "\n";
    return text;
}

/// Per lab, over the submissions graded under the grading now: the mean score, and each check's
/// pass rate among the submissions that made it (speed under --no-speed is made by none).
std::string labTable(const std::vector<GradebookEntry>& entries) {
    if (entries.empty()) return "<p>No submission graded under this rubric yet.</p>\n";
    std::ostringstream html;
    html << "<table><tr><th>lab</th><th>mean score</th>";
    for (CheckKind check : AllChecks) html << "<th>" << checkName(check) << " passed</th>";
    html << "</tr>\n";
    for (Lab lab : AllLabs) {
        double sum = 0, max = 0;
        std::map<CheckKind, std::pair<int, int>> passedOfMade;
        for (const GradebookEntry& e : entries) {
            const nlohmann::json labResult =
                e.result.value("labs", nlohmann::json::object())
                    .value(std::string(labName(lab)), nlohmann::json::object());
            sum += labResult.value("score", 0.0);
            max = std::max(max, labResult.value("max_score", 0.0));
            const nlohmann::json checks = labResult.value("checks", nlohmann::json::object());
            for (CheckKind check : AllChecks) {
                const nlohmann::json c =
                    checks.value(std::string(checkName(check)), nlohmann::json());
                if (!c.is_object() || !c.value("graded_here", true)) continue;
                ++passedOfMade[check].second;
                passedOfMade[check].first += c.value("passed", false);
            }
        }
        html << "<tr><td>" << labName(lab) << "</td><td>"
             << number(std::round(100 * sum / entries.size()) / 100) << " / " << number(max)
             << "</td>";
        for (CheckKind check : AllChecks) {
            const auto [passed, made] = passedOfMade[check];
            html << "<td>"
                 << (made == 0 ? std::string("not checked")
                               : number(std::round(100.0 * passed / made)) + "% (" +
                                     std::to_string(passed) + " of " + std::to_string(made) + ")")
                 << "</td>";
        }
        html << "</tr>\n";
    }
    return html.str() + "</table>\n";
}

/// Where each graded submission's time went (result.json's seconds_by_phase), a row each, and
/// the median: what tells an instructor how long a class takes, and why.
std::string timeTable(const std::vector<GradebookEntry>& entries) {
    const std::vector<std::pair<const char*, const char*>> phases = {{"intake", "intake"},
                                                                     {"compile", "compile"},
                                                                     {"correctness", "correctness"},
                                                                     {"race_check", "race check"},
                                                                     {"speed", "speed"}};
    std::vector<std::vector<double>> columns(phases.size() + 1);
    std::ostringstream rows;
    for (const GradebookEntry& e : entries) {
        if (e.result.is_null() || !e.result.contains("seconds_by_phase")) continue;
        const nlohmann::json& spent = e.result.at("seconds_by_phase");
        rows << "<tr><td>" << escapeXml(e.id) << "</td>";
        for (size_t i = 0; i < phases.size(); ++i) {
            const double s = spent.value(phases[i].first, 0.0);
            columns[i].push_back(s);
            rows << "<td>" << number(std::round(10 * s) / 10) << "</td>";
        }
        const double total = e.result.value("seconds", 0.0);
        columns.back().push_back(total);
        rows << "<td>" << number(std::round(total)) << "</td><td>"
             << escapeXml(e.result.value("how", "graded")) << "</td></tr>\n";
    }
    if (columns.back().empty()) return "<p>No grading times yet.</p>\n";
    std::ostringstream html;
    html << "<table><tr><th>id</th>";
    for (const auto& phase : phases) html << "<th>" << phase.second << " (s)</th>";
    html << "<th>total (s)</th><th>how</th></tr>\n<tr><td><b>median</b></td>";
    for (std::vector<double>& column : columns) {
        std::sort(column.begin(), column.end());
        html << "<td><b>" << number(std::round(10 * column[column.size() / 2]) / 10) << "</b></td>";
    }
    html << "<td></td></tr>\n" << rows.str() << "</table>\n";
    return html.str();
}

std::string summaryPage(const std::vector<GradebookEntry>& allEntries, const GradingNow& now,
                        const std::optional<std::vector<SimilarLabs>>& similar,
                        const std::vector<RegradeComparison>& regrades,
                        const std::vector<ClassFigures>& history) {
    int graded = 0, pending = 0, stale = 0, late = 0, timeUnknown = 0, lowered = 0;
    double sum = 0, finalSum = 0; // of the totals that count, before and after late penalties
    // (lab, diagnosis) -> the submissions it was made of
    std::map<std::pair<std::string, std::string>, std::vector<std::string>> diagnoses;
    std::vector<GradebookEntry> entries; // those with a total out of today's maximum
    for (const GradebookEntry& e : allEntries) {
        pending += e.pending;
        const std::string isLate = lateness(e, now);
        late += isLate == "yes";
        timeUnknown += isLate == "unknown";
        lowered += loweredUndecided(e, now);
        if (e.result.is_null()) continue;
        stale += !staleness(e.result, now).empty();
        if (!countedTotal(e, now)) continue;
        entries.push_back(e);
        ++graded;
        const double max = e.result.value("max_score", 0.0);
        sum += max > 0 ? *countedTotal(e, now) / max : 0;
        finalSum += max > 0 ? finalTotal(e, now).value_or(0) / max : 0;
        for (const auto& d : e.result.value("diagnoses", nlohmann::json::array()))
            if (d.value("check", "") == std::string(checkName(CheckKind::Correctness)) ||
                d.value("diagnosis", "") == "too noisy" || d.value("diagnosis", "") == "too slow")
                diagnoses[{d.value("lab", ""), d.value("diagnosis", "")}].push_back(e.id);
    }
    std::vector<std::pair<int, std::pair<std::string, std::string>>> common;
    for (const auto& [key, ids] : diagnoses) common.push_back({static_cast<int>(ids.size()), key});
    std::sort(common.begin(), common.end(), [](const auto& a, const auto& b) {
        return a.first != b.first ? a.first > b.first : a.second < b.second;
    });

    std::ostringstream html;
    html << "<!doctype html><html><head><meta charset=\"utf-8\"><title>PathLab batch</title><style>"
         << pageStyle() << "</style></head><body>\n"
         << "<h1>PathLab batch: " << graded << " of " << allEntries.size()
         << " submissions graded</h1>\n";
    if (graded > 0)
        html << "<p>Mean total: " << number(std::round(1000 * sum / graded) / 10)
             << "% of the maximum (" << number(now.maxScore) << " points)"
             << (finalSum < sum ? ", " + number(std::round(1000 * finalSum / graded) / 10) +
                                      "% after the late policy's penalties"
                                : std::string())
             << ".</p>\n";
    if (pending + stale + late > 0)
        html << "<p>" << pending << " pending, " << stale
             << " stale (graded under another rubric or other "
             << "scenes), " << late << " late.</p>\n";
    if (timeUnknown > 0)
        html << "<p><b>" << timeUnknown
             << " handed in with no time known</b> (late: <code>unknown</code>): the submission "
                "told none it could have been handed in at, and nothing is taken off; give "
                "their times with <code>--times</code>.</p>\n";
    if (lowered > 0)
        html << "<p><b>" << lowered
             << " total(s) lowered by a regrade of the same files</b>, withheld from lms.csv "
                "until the rubric's <code>regrades.lower_scores</code> says <code>replace</code> "
                "or <code>keep_higher</code> (their status says from what to what).</p>\n";
    html << "<h2>Scores</h2>\n"
         << histogram(entries) << "<h2>Labs</h2>\n"
         << labTable(entries) << labHistograms(entries) << "<h2>Most common diagnoses</h2>\n"
         << "<table><tr><th>submissions</th><th>lab</th><th>diagnosis</th><th>whose</th></tr>\n";
    for (const auto& [count, key] : common) {
        std::string whose;
        for (const std::string& id : diagnoses[key])
            whose += (whose.empty() ? "" : ", ") + ("<a href=\"submissions/" + escapeXml(id) +
                                                    "/index.html\">" + escapeXml(id) + "</a>");
        html << "<tr><td>" << count << "</td><td>" << escapeXml(key.first) << "</td><td>"
             << escapeXml(key.second) << "</td><td>" << whose << "</td></tr>\n";
    }
    html << "</table>\n<h2>Over time</h2>\n<p>The class when each batch into this folder "
            "finished (<code>history.jsonl</code>): the mean total and each lab's mean score, as "
            "percentages of their maxima, and the share of those graded whose lab passed its "
            "correctness check.</p>\n"
         << classHistoryHtml(history) << "<h2>Regrades</h2>\n"
         << regradesHtml(regrades) << "<h2>Similar submissions</h2>\n"
         << similarityTable(similar)
         << "<h2>Submissions</h2>\n<table><tr><th>id</th><th>score</th><th>late</th><th>status</"
            "th></tr>\n";
    for (const GradebookEntry& e : allEntries) {
        const std::string link = "submissions/" + e.id + "/index.html";
        const std::optional<double> total = countedTotal(e, now);
        const std::optional<double> lateTotal = finalTotal(e, now);
        // The score the LMS gets, and the graded one beside it where the late policy lowered it.
        std::string score = total ? number(*total) + " / " + number(now.maxScore) : "";
        if (total && lateTotal && *lateTotal != *total)
            score = number(*lateTotal) + " / " + number(now.maxScore) + " (graded " +
                    number(*total) + ")";
        const std::optional<LateCost> late = lateCostOf(e, now);
        html << "<tr><td>"
             << (e.result.is_null()
                     ? escapeXml(e.id)
                     : "<a href=\"" + escapeXml(link) + "\">" + escapeXml(e.id) + "</a>")
             << "</td><td>" << score << "</td><td>" << lateness(e, now)
             << (late && !late->labs.empty() ? ": " + escapeXml(late->labs) : "") << "</td><td>"
             << escapeXml(statusOf(e, now)) << "</td></tr>\n";
    }
    html << "</table>\n<h2>Grading time</h2>\n<p>Wall-clock seconds of each submission's "
            "last grading, by phase (a re-score measures nothing and takes none).</p>\n"
         << timeTable(allEntries) << "</body></html>\n";
    return html.str();
}

} // namespace

GradebookEntry readGradebookEntry(const std::string& out, const std::string& id,
                                  const std::string& submission) {
    GradebookEntry entry{id, submission, nullptr, "", false, std::nullopt};
    std::ifstream in(out + "/submissions/" + id + "/result.json");
    if (!in) {
        entry.problem = "no result (see submissions/" + id + "/grader.log)";
        return entry;
    }
    try {
        entry.result = nlohmann::json::parse(in);
    } catch (const nlohmann::json::exception& e) {
        entry.problem = std::string("its result.json is unreadable: ") + e.what();
        return entry;
    }
    entry.higherEarlier = higherEarlierTotal(out + "/submissions/" + id, entry.result);
    return entry;
}

std::optional<double> countedTotal(const GradebookEntry& e, const GradingNow& now) {
    if (e.result.is_null() || e.result.value("max_score", 0.0) != now.maxScore) return std::nullopt;
    if (e.higherEarlier && now.lowerScores == LowerScores::KeepHigher)
        return e.higherEarlier->score;
    return e.result.value("score", 0.0);
}

std::string staleness(const nlohmann::json& result, const GradingNow& now) {
    const nlohmann::json under = result.value("graded_under", nlohmann::json::object());
    if (under.value("rubric_hash", "") != now.rubricHash) return "graded under another rubric";
    if (under.value("scenes_hash", "") != now.scenesHash) return "graded on other scenes";
    if (result.value("max_score", 0.0) != now.maxScore)
        return "graded out of " + number(result.value("max_score", 0.0)) + ", not " +
               number(now.maxScore);
    return "";
}

Regrade regradeNeeded(const nlohmann::json& result, const GradingNow& now) {
    if (staleness(result, now).empty()) return Regrade::None;
    const nlohmann::json under = result.value("graded_under", nlohmann::json::object());
    const bool sameMeasurements = under.value("scenes_hash", "") == now.scenesHash &&
                                  under.value("kit_version", "") == PATHLAB_VERSION &&
                                  under.value("measurement_hash", "") == now.measurementHash &&
                                  (under.value("speed_measured", false) || !now.measuresSpeed);
    return sameMeasurements ? Regrade::Rescore : Regrade::Measure;
}

void writeGradebook(const std::string& out, const std::vector<GradebookEntry>& entries,
                    const GradingNow& now, const std::optional<std::vector<SimilarLabs>>& similar) {
    std::vector<RegradeComparison> regrades;
    for (const GradebookEntry& e : entries)
        if (!e.result.is_null())
            if (auto c = compareWithAttemptBefore(e.id, out + "/submissions/" + e.id, e.result))
                regrades.push_back(*c);
    writeFileAtomically(out + "/gradebook.csv", csv(entries, now));
    writeFileAtomically(out + "/lms.csv", lmsCsv(entries, now));
    writeFileAtomically(out + "/regrades.csv", regradesCsv(regrades));
    if (similar) writeFileAtomically(out + "/similarity.csv", similarityCsv(*similar));
    // A finished batch (its similarity report made) is a point in the class's history.
    std::vector<ClassFigures> history = readClassHistory(out);
    if (similar) {
        const ClassFigures figures =
            classFiguresNow(entries, now, isoTime(static_cast<long long>(std::time(nullptr))));
        if (figures.graded > 0) {
            history.push_back(figures);
            writeClassHistory(out, history);
        }
    }
    writeFileAtomically(out + "/summary.html",
                        summaryPage(entries, now, similar, regrades, history));
}

} // namespace pathlab::grader
