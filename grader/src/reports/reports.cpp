#include "reports/reports.h"

#include "reports/page_style.h"
#include "reports/tile_z_map.h"

#include "pathlab/images/image_io.h"
#include "pathlab/render/render_stats.h"
#include "pathlab/support/whole_file.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <sstream>

namespace pathlab::grader {

std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\n") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

std::string escapeXml(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        default: out += c;
        }
    }
    return out;
}

namespace {

/// The sum over the labs of one of LabGrade's counts of points.
double sumOfLabs(const std::vector<LabGrade>& labs, double (LabGrade::*points)() const) {
    double sum = 0;
    for (const LabGrade& lab : labs) sum += (lab.*points)();
    return sum;
}

} // namespace

double GradeReport::score() const { return sumOfLabs(labs, &LabGrade::score); }
double GradeReport::maxScore() const { return sumOfLabs(labs, &LabGrade::maxScore); }
double GradeReport::pointsNotGradedHere() const {
    return sumOfLabs(labs, &LabGrade::pointsNotGradedHere);
}
double GradeReport::pointsAtRisk() const { return sumOfLabs(labs, &LabGrade::pointsAtRisk); }

namespace {

/// "8/8", or "8/8 (+2 speed: graded by the instructor)" where a check is not graded here, with
/// "; 2 of them at risk" where this build's own figures say those would likely be lost.
std::string scoreText(double score, double maxScore, double notGradedHere, double atRisk) {
    char text[160];
    if (notGradedHere > 0 && atRisk > 0)
        std::snprintf(text, sizeof text,
                      "%g/%g (+%g speed: graded by the instructor; %g of them at risk)", score,
                      maxScore, notGradedHere, atRisk);
    else if (notGradedHere > 0)
        std::snprintf(text, sizeof text, "%g/%g (+%g speed: graded by the instructor)", score,
                      maxScore, notGradedHere);
    else
        std::snprintf(text, sizeof text, "%g/%g", score, maxScore);
    return text;
}

/// "; late: 20% off, 38.4 counts" for a late submission's report (GradeReport::latePenalty).
std::string lateText(const GradeReport& report) {
    if (report.latePenalty <= 0) return "";
    char text[120];
    std::snprintf(text, sizeof text, "; late: %g%% off, %g counts", 100 * report.latePenalty,
                  report.score() * (1 - report.latePenalty));
    return text;
}

/// A check's summary and details, and the hidden scenes' pass or fail as `hidden` says.
std::string checkText(const CheckResult& c, HiddenVerdicts hidden = HiddenVerdicts::Shown) {
    std::string text = c.summary;
    for (const std::string& d : c.details) text += "\n  " + d;
    if (!c.hiddenSceneDetails.empty() && hidden == HiddenVerdicts::InTheirOwnTest)
        text += "\n  hidden scenes: in the test \"hidden scenes\" of this lab";
    for (const std::string& d : c.hiddenSceneDetails)
        if (hidden == HiddenVerdicts::Shown) text += "\n  " + d;
    return text;
}

std::string base64(const std::string& bytes) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) |
                           (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                           static_cast<unsigned char>(bytes[i + 2]);
        for (int k = 3; k >= 0; --k) out += table[(v >> (6 * k)) & 63];
    }
    if (i < bytes.size()) {
        unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
        if (i + 1 < bytes.size()) v |= static_cast<unsigned char>(bytes[i + 1]) << 8;
        out += table[(v >> 18) & 63];
        out += table[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? table[(v >> 6) & 63] : '=';
        out += '=';
    }
    return out;
}

} // namespace

std::vector<LabRatio> labRatios(const GradeReport& report) {
    const LabGrade* branching = nullptr;
    for (const LabGrade& l : report.labs)
        if (l.lab == Lab::Branching) branching = &l;
    std::vector<LabRatio> ratios;
    if (!branching || !(branching->studentSamplesPerSecond > 0)) return ratios;
    for (const LabGrade& l : report.labs) {
        if (l.lab == Lab::Branching || !(l.studentSamplesPerSecond > 0)) continue;
        const bool referenceKnown =
            l.solutionSamplesPerSecond > 0 && branching->solutionSamplesPerSecond > 0;
        ratios.push_back({std::string(labName(l.lab)) + "/branching",
                          l.studentSamplesPerSecond / branching->studentSamplesPerSecond,
                          referenceKnown
                              ? l.solutionSamplesPerSecond / branching->solutionSamplesPerSecond
                              : 0});
    }
    return ratios;
}

std::string terminalReport(const GradeReport& report, bool colour, HiddenVerdicts hidden) {
    const char* green = colour ? "\033[32m" : "";
    const char* red = colour ? "\033[31m" : "";
    const char* reset = colour ? "\033[0m" : "";
    std::ostringstream out;
    char line[512];
    // A column per check, 13 wide as its cells; the lab's 12.
    out << std::left << std::setw(12) << "lab";
    for (CheckKind check : AllChecks) out << std::setw(13) << checkName(check);
    out << "score\n" << std::right;
    for (const LabGrade& lab : report.labs) {
        out << std::string(labName(lab.lab)) << std::string(12 - labName(lab.lab).size(), ' ');
        for (CheckKind check : AllChecks) {
            // A check this grading did not run (--no-speed) keeps its column, empty.
            auto found = std::find_if(lab.checks.begin(), lab.checks.end(),
                                      [&](const CheckResult& c) { return c.kind == check; });
            if (found == lab.checks.end()) {
                out << std::setw(13) << std::left << "-" << std::right;
                continue;
            }
            const CheckResult& c = *found;
            if (c.gradedHere)
                std::snprintf(line, sizeof line, "%s %g/%g", c.passed ? "pass" : "FAIL", c.score,
                              c.maxScore);
            else
                std::snprintf(line, sizeof line, c.atRisk ? "(+%g) RISK" : "(+%g)", c.maxScore);
            std::string cell = line;
            cell.resize(std::max<size_t>(cell.size() + 1, 13), ' ');
            out << (c.atRisk ? red : !c.gradedHere ? "" : c.passed ? green : red) << cell << reset;
        }
        out << scoreText(lab.score(), lab.maxScore(), lab.pointsNotGradedHere(), lab.pointsAtRisk())
            << "\n";
    }
    out << "total "
        << scoreText(report.score(), report.maxScore(), report.pointsNotGradedHere(),
                     report.pointsAtRisk());
    std::snprintf(line, sizeof line, " in %.0f s\n", report.seconds);
    out << line;
    for (const LabGrade& lab : report.labs)
        for (const CheckResult& c : lab.checks)
            out << "\n"
                << labName(lab.lab) << " " << c.name() << ": "
                << (c.atRisk || (!c.passed && c.gradedHere) ? red : "") << checkText(c, hidden)
                << reset;
    out << "\n";
    const auto ratios = labRatios(report);
    if (!ratios.empty()) {
        out << "\nspeed ratios between labs: samples per CPU-second in the grader's timed runs"
            << (report.ratiosMeasuredOn.empty() ? "" : " (" + report.ratiosMeasuredOn + ")")
            << " ÷ branching's\n"
            << "                              yours   reference\n";
        for (const LabRatio& r : ratios) {
            std::snprintf(line, sizeof line, "  %-26s %6.2f   ", r.name.c_str(), r.student);
            out << line;
            if (r.reference > 0)
                std::snprintf(line, sizeof line, "%6.2f\n", r.reference);
            else
                std::snprintf(line, sizeof line, "%6s\n", "-");
            out << line;
        }
        out << "  reference: "
            << (report.ratiosReference.empty()
                    ? "the reference solutions, timed now beside your labs"
                    : report.ratiosReference)
            << "\n  (compare the ratios, not the samples per CPU-second: those depend on the "
               "machine; CPU time changes little when other programs run, wall-clock time "
               "does)\n";
    }
    for (const std::string& note : report.notes) out << "note: " << note << "\n";
    return out.str();
}

/// A speed figure, or null where it was not measured (a grading without speed, or a lab that
/// did not run): 0 would read as a measured standstill.
static nlohmann::json measuredOrNull(double figure) {
    if (!(figure > 0) || !std::isfinite(figure)) return nullptr;
    return figure;
}

std::string jsonReport(const GradeReport& report) {
    nlohmann::json labs = nlohmann::json::array();
    for (const LabGrade& lab : report.labs) {
        nlohmann::json checks = nlohmann::json::array();
        for (const CheckResult& c : lab.checks)
            checks.push_back({{"name", c.name()},
                              {"score", c.score},
                              {"max_score", c.maxScore},
                              {"passed", c.passed},
                              {"graded_here", c.gradedHere},
                              {"at_risk", c.atRisk},
                              {"summary", c.summary},
                              {"details", c.details},
                              {"hidden_scenes", c.hiddenSceneDetails}});
        auto rays = [](const RaysPerSample& r) {
            return nlohmann::json{{"camera", r.camera}, {"bounce", r.bounce}, {"shadow", r.shadow}};
        };
        labs.push_back(
            {{"lab", labName(lab.lab)},
             {"score", lab.score()},
             {"max_score", lab.maxScore()},
             {"checks", checks},
             {"samples_per_second",
              {{"student", measuredOrNull(lab.studentSamplesPerSecond)},
               {"solution", measuredOrNull(lab.solutionSamplesPerSecond)}}},
             {"rays_per_sample",
              {{"student", rays(lab.studentRays)}, {"solution", rays(lab.solutionRays)}}},
             {"variance_per_sample",
              {{"student", lab.studentVariance}, {"solution", lab.solutionVariance}}},
             {"efficiency_ratio", measuredOrNull(lab.efficiencyRatio)}});
    }
    nlohmann::json ratios = nlohmann::json::object();
    for (const LabRatio& r : labRatios(report))
        ratios[r.name] = {{"student", r.student}, {"reference", r.reference}};
    nlohmann::json attempts = nlohmann::json::array();
    for (const GradeReport::Attempt& a : report.earlierAttempts)
        attempts.push_back({{"attempt", a.number},
                            {"score", a.score},
                            {"max_score", a.maxScore},
                            {"graded_at", a.gradedAt},
                            {"how", a.how}});
    const nlohmann::json j = {{"kit_version", PATHLAB_VERSION},
                              {"score", report.score()},
                              {"max_score", report.maxScore()},
                              {"points_not_graded_here", report.pointsNotGradedHere()},
                              {"points_at_risk", report.pointsAtRisk()},
                              {"seconds", report.seconds},
                              {"labs", labs},
                              {"speed_ratios", ratios},
                              {"notes", report.notes},
                              {"earlier_attempts", attempts}};
    return j.dump(2) + "\n";
}

std::string junitReport(const GradeReport& report) {
    int tests = 0, failures = 0;
    for (const LabGrade& lab : report.labs)
        for (const CheckResult& c : lab.checks) ++tests, failures += c.gradedHere && !c.passed;
    std::ostringstream out;
    out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        << "<testsuites tests=\"" << tests << "\" failures=\"" << failures << "\" time=\""
        << report.seconds << "\">\n"
        << "  <testsuite name=\"pathlab-grader\" tests=\"" << tests << "\" failures=\"" << failures
        << "\">\n";
    for (const LabGrade& lab : report.labs) {
        for (const CheckResult& c : lab.checks) {
            out << "    <testcase classname=\"" << labName(lab.lab) << "\" name=\""
                << escapeXml(c.name()) << "\">\n";
            if (!c.gradedHere)
                out << "      <skipped message=\"" << escapeXml(c.summary) << "\"/>\n";
            else if (!c.passed)
                out << "      <failure message=\"" << escapeXml(c.summary) << "\">"
                    << escapeXml(checkText(c)) << "</failure>\n";
            else
                out << "      <system-out>" << escapeXml(checkText(c)) << "</system-out>\n";
            out << "    </testcase>\n";
        }
    }
    out << "  </testsuite>\n</testsuites>\n";
    return out.str();
}

namespace {

/// Gradescope's leaderboard (its "leaderboard" array; Gradescope shows it under the pseudonyms the
/// students choose): the total, then per lab its efficiency over the reference solution's, the
/// time to equal noise, which only a correct lab has (0 otherwise, ranked last), higher first.
nlohmann::json gradescopeLeaderboard(const GradeReport& report) {
    nlohmann::json board = nlohmann::json::array();
    board.push_back({{"name", "total"}, {"value", report.score() * (1 - report.latePenalty)}});
    for (const LabGrade& lab : report.labs) {
        const bool correct = !lab.checks.empty() && lab.checks.front().passed;
        const double ratio = correct ? lab.efficiencyRatio : 0;
        board.push_back({{"name", std::string(labName(lab.lab)) + ": efficiency / reference"},
                         {"value", std::round(ratio * 1000) / 1000}});
    }
    return board;
}

} // namespace

std::string gradescopeReport(const GradeReport& report, const std::string& hiddenVisibility,
                             bool leaderboard) {
    nlohmann::json tests = nlohmann::json::array();
    for (const LabGrade& lab : report.labs) {
        for (const CheckResult& c : lab.checks)
            if (c.gradedHere)
                tests.push_back({{"name", std::string(labName(lab.lab)) + ": " + c.name()},
                                 {"score", c.score},
                                 {"max_score", c.maxScore},
                                 {"status", c.passed ? "passed" : "failed"},
                                 {"output", checkText(c, HiddenVerdicts::InTheirOwnTest)},
                                 {"visibility", "visible"}});
        // The hidden scenes' verdicts, without points of their own (they are in correctness's),
        // shown when the instructor's rubric says.
        for (const CheckResult& c : lab.checks) {
            if (c.hiddenSceneDetails.empty()) continue;
            std::string output;
            bool passed = true;
            for (const std::string& d : c.hiddenSceneDetails) {
                output += (output.empty() ? "" : "\n") + d;
                passed = passed && d.find(HiddenSceneDiffers) == std::string::npos;
            }
            tests.push_back({{"name", std::string(labName(lab.lab)) + ": hidden scenes"},
                             {"score", 0},
                             {"max_score", 0},
                             {"status", passed ? "passed" : "failed"},
                             {"output", output},
                             {"visibility", hiddenVisibility}});
        }
    }
    nlohmann::json j = {{"score", report.score() * (1 - report.latePenalty)},
                        {"execution_time", static_cast<int>(report.seconds + 0.5)},
                        {"output", terminalReport(report, false, HiddenVerdicts::InTheirOwnTest)},
                        {"tests", tests}};
    if (leaderboard) j["leaderboard"] = gradescopeLeaderboard(report);
    return j.dump(2) + "\n";
}

std::string prairieLearnReport(const GradeReport& report) {
    nlohmann::json tests = nlohmann::json::array();
    for (const LabGrade& lab : report.labs)
        for (const CheckResult& c : lab.checks)
            if (c.gradedHere)
                tests.push_back({{"name", std::string(labName(lab.lab)) + ": " + c.name()},
                                 {"description", "lab " + std::to_string(labNumber(lab.lab)) +
                                                     ", " + std::string(labName(lab.lab)) +
                                                     ": the " + c.name() + " check"},
                                 {"points", c.score},
                                 {"max_points", c.maxScore},
                                 {"message", c.passed ? "passed" : "failed"},
                                 {"output", checkText(c, HiddenVerdicts::LeftOut)}});
    const double max = report.maxScore();
    const nlohmann::json j = {
        {"gradable", true},
        {"score", max > 0 ? report.score() * (1 - report.latePenalty) / max : 0.0},
        {"message",
         scoreText(report.score(), max, report.pointsNotGradedHere(), report.pointsAtRisk()) +
             lateText(report)},
        {"output", terminalReport(report, false, HiddenVerdicts::LeftOut)},
        {"tests", tests}};
    return j.dump(2) + "\n";
}

void writeHtmlReport(const GradeReport& report, const std::string& folder) {
    namespace fs = std::filesystem;
    fs::create_directories(folder);
    auto png = [&](int w, int h, const std::vector<float>& rgb) {
        const std::string path = folder + "/.picture.png";
        writeImage(path, w, h, rgb);
        const std::string data = base64(readFile(path));
        fs::remove(path);
        return renderImage(data, w, h);
    };
    auto tileMap = [&](int w, int h, const std::vector<unsigned char>& rgb) {
        const std::string path = folder + "/.tiles.png";
        writeDisplayImage(path, w, h, rgb);
        const std::string data = base64(readFile(path));
        fs::remove(path);
        return renderImage(data, w, h);
    };
    std::ostringstream html;
    html << "<!doctype html><html><head><meta charset=\"utf-8\"><title>PathLab grade</title><style>"
         << pageStyle() << "</style></head><body>\n<h1>PathLab grade: "
         << escapeXml(scoreText(report.score(), report.maxScore(), report.pointsNotGradedHere(),
                                report.pointsAtRisk()))
         << "</h1>\n"
         << "<table><tr><th>lab</th><th>check</th><th>score</th><th>result</th></tr>\n";
    for (const LabGrade& lab : report.labs)
        for (const CheckResult& c : lab.checks)
            html << "<tr><td>" << labName(lab.lab) << "</td><td>" << c.name() << "</td><td>"
                 << c.score << " / " << c.maxScore << "</td><td class=\""
                 << (c.atRisk        ? "fail\">graded by the instructor: at risk"
                     : !c.gradedHere ? "\">graded by the instructor"
                     : c.passed      ? "pass\">pass"
                                     : "fail\">FAIL")
                 << "</td></tr>\n";
    html << "</table>\n";
    for (const LabGrade& lab : report.labs) {
        html << "<h2>" << labName(lab.lab) << "</h2>\n";
        for (const CheckResult& c : lab.checks)
            html << "<h3>" << c.name() << "</h3><pre>" << escapeXml(checkText(c)) << "</pre>\n";
        for (const auto& p : lab.pictures) {
            if (p.student.empty() || p.reference.size() != p.student.size()) continue;
            const std::vector<unsigned char> tileZs =
                tileZImage(p.regionT, p.regionP, p.tilesPerSide, p.width, p.height);
            const bool tiles = !tileZs.empty();
            html << "<p>" << p.scene << ": yours, the reference"
                 << (tiles ? ", and each tile's z-score of its mean against the reference: what "
                             "the correctness check tests (a correct lab's tiles stay pale)"
                           : "")
                 << "</p><p>" << png(p.width, p.height, p.student) << " "
                 << png(p.width, p.height, p.reference);
            if (tiles) html << " " << tileMap(p.width, p.height, tileZs);
            html << "</p>\n";
            if (tiles) html << tileZLegendHtml();
        }
    }
    if (!report.earlierAttempts.empty()) {
        html << "<h2>Earlier attempts</h2>\n<table><tr><th>attempt</th><th>score</th><th>graded "
                "(UTC)</th><th>how</th></tr>\n";
        for (const GradeReport::Attempt& a : report.earlierAttempts)
            html << "<tr><td><a href=\"attempts/" << a.number << "/index.html\">" << a.number
                 << "</a></td><td>" << a.score << " / " << a.maxScore << "</td><td>"
                 << escapeXml(a.gradedAt) << "</td><td>" << escapeXml(a.how) << "</td></tr>\n";
        html << "</table>\n";
    }
    html << "</body></html>\n";
    writeFileAtomically(folder + "/index.html", html.str());
}

} // namespace pathlab::grader
