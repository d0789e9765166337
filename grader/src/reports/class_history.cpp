#include "reports/class_history.h"

#include "checks/check_kind.h"
#include "reports/reports.h"

#include "pathlab/render/lab_registry.h"
#include "pathlab/support/whole_file.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <fstream>
#include <sstream>

namespace pathlab::grader {

namespace {

std::string percent(double value) {
    std::ostringstream text;
    text << std::round(value) << "%";
    return text.str();
}

nlohmann::json toJson(const ClassFigures& f) {
    nlohmann::json labs = nlohmann::json::object();
    for (const auto& [lab, mean] : f.labMean)
        labs[lab] = {{"mean", mean}, {"correctness", f.labCorrectness.at(lab)}};
    return {{"at", f.at},
            {"graded", f.graded},
            {"submissions", f.submissions},
            {"mean_total", f.meanTotal},
            {"labs", labs}};
}

ClassFigures fromJson(const nlohmann::json& j) {
    ClassFigures f;
    f.at = j.at("at").get<std::string>();
    f.graded = j.at("graded").get<int>();
    f.submissions = j.at("submissions").get<int>();
    f.meanTotal = j.at("mean_total").get<double>();
    for (const auto& [lab, figures] : j.at("labs").items()) {
        f.labMean[lab] = figures.at("mean").get<double>();
        f.labCorrectness[lab] = figures.at("correctness").get<double>();
    }
    return f;
}

// The chart's layout, in SVG units (CSS pixels), for 11-pixel text: the plot, the dates under
// it, the legend to its right.
constexpr int Width = 640, Height = 250;
constexpr int PlotLeft = 40, PlotRight = 470, PlotTop = 12, PlotBottom = 200;
constexpr int DateBaseline = PlotBottom + 16, TitleBaseline = DateBaseline + 18;
constexpr int LegendX = PlotRight + 20, LegendPitch = 16;
const char* const Colours[] = {"#222222", "#4a7ab5", "#c0504d", "#9bbb59",
                               "#8064a2", "#f79646", "#4bacc6", "#7f7f7f"};

std::string chart(const std::vector<ClassFigures>& history) {
    const size_t n = history.size();
    auto x = [&](size_t i) {
        return PlotLeft + (PlotRight - PlotLeft) * static_cast<int>(i) / static_cast<int>(n - 1);
    };
    auto y = [](double percentOfMax) {
        return PlotBottom -
               static_cast<int>(std::lround((PlotBottom - PlotTop) *
                                            std::clamp(percentOfMax, 0.0, 100.0) / 100));
    };
    std::ostringstream svg;
    svg << "<svg width=\"" << Width << "\" height=\"" << Height << "\" viewBox=\"0 0 " << Width
        << " " << Height << "\" xmlns=\"http://www.w3.org/2000/svg\" "
        << "font-family=\"sans-serif\" font-size=\"11\">\n";
    for (int level = 0; level <= 100; level += 25)
        svg << "<line x1=\"" << PlotLeft << "\" x2=\"" << PlotRight << "\" y1=\"" << y(level)
            << "\" y2=\"" << y(level) << "\" stroke=\"#dddddd\"/>\n<text x=\"" << PlotLeft - 4
            << "\" y=\"" << y(level) + 4 << "\" text-anchor=\"end\">" << level << "%</text>\n";
    // When, under every batch or under every k-th where they would overlap: month, day and
    // time ("12-07 14:05"), as batches of one day are told apart by their hour.
    const size_t step =
        std::max<size_t>(1, (n * 80 + (PlotRight - PlotLeft) - 1) / (PlotRight - PlotLeft));
    for (size_t i = 0; i < n; i += step) {
        const std::string& at = history[i].at; // 2026-12-07T14:05:00Z
        const std::string when =
            at.size() >= 16 ? at.substr(5, 5) + " " + at.substr(11, 5) : at.substr(0, 10);
        svg << "<text x=\"" << x(i) << "\" y=\"" << DateBaseline << "\" text-anchor=\"middle\">"
            << escapeXml(when) << "</text>\n";
    }
    svg << "<text x=\"" << (PlotLeft + PlotRight) / 2 << "\" y=\"" << TitleBaseline
        << "\" text-anchor=\"middle\">batch finished (UTC), % of the maximum</text>\n";
    std::vector<std::pair<std::string, std::vector<double>>> lines = {{"total", {}}};
    for (const ClassFigures& f : history) lines[0].second.push_back(f.meanTotal);
    for (Lab lab : AllLabs) {
        const std::string name(labName(lab));
        std::vector<double> values;
        for (const ClassFigures& f : history)
            values.push_back(f.labMean.count(name) ? f.labMean.at(name) : 0);
        lines.push_back({name, values});
    }
    for (size_t k = 0; k < lines.size(); ++k) {
        const char* colour = Colours[k % std::size(Colours)];
        // Labs of equal means would hide one another: each lab's line is moved by a pixel or
        // two of its own, and the legend gives each line's last value.
        const int shift = k == 0 ? 0 : 2 * static_cast<int>(k) - static_cast<int>(lines.size());
        svg << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\""
            << (k == 0 ? 3 : 1.5) << "\" points=\"";
        for (size_t i = 0; i < n; ++i)
            svg << x(i) << "," << std::clamp(y(lines[k].second[i]) + shift, 0, Height) << " ";
        svg << "\"/>\n<text x=\"" << LegendX << "\" y=\"" << PlotTop + 8 + LegendPitch * k
            << "\" fill=\"" << colour << "\">" << escapeXml(lines[k].first)
            << (k == 0 ? " (mean)" : "") << " " << percent(lines[k].second.back()) << "</text>\n";
    }
    svg << "</svg>\n";
    return svg.str();
}

} // namespace

ClassFigures classFiguresNow(const std::vector<GradebookEntry>& entries, const GradingNow& now,
                             const std::string& at) {
    ClassFigures f;
    f.at = at;
    f.submissions = static_cast<int>(entries.size());
    std::map<std::string, double> labSum, correct;
    double totalSum = 0;
    for (const GradebookEntry& e : entries) {
        const std::optional<double> total = countedTotal(e, now);
        if (!total || e.pending) continue;
        ++f.graded;
        totalSum += now.maxScore > 0 ? *total / now.maxScore : 0;
        const nlohmann::json labs = e.result.value("labs", nlohmann::json::object());
        for (Lab lab : AllLabs) {
            const std::string name(labName(lab));
            const nlohmann::json graded = labs.value(name, nlohmann::json::object());
            const double max = graded.value("max_score", 0.0);
            labSum[name] += max > 0 ? graded.value("score", 0.0) / max : 0;
            const nlohmann::json check =
                graded.value("checks", nlohmann::json::object())
                    .value(std::string(checkName(CheckKind::Correctness)), nlohmann::json());
            correct[name] += check.is_object() && check.value("passed", false);
        }
    }
    if (f.graded == 0) return f;
    f.meanTotal = 100 * totalSum / f.graded;
    for (Lab lab : AllLabs) {
        const std::string name(labName(lab));
        f.labMean[name] = 100 * labSum[name] / f.graded;
        f.labCorrectness[name] = 100 * correct[name] / f.graded;
    }
    return f;
}

std::vector<ClassFigures> readClassHistory(const std::string& out) {
    std::vector<ClassFigures> history;
    std::ifstream in(out + "/history.jsonl");
    std::string line;
    while (std::getline(in, line)) {
        try {
            history.push_back(fromJson(nlohmann::json::parse(line)));
        } catch (const nlohmann::json::exception&) {
            // A line cut short or edited by hand: the rest still tell the story.
        }
    }
    return history;
}

void writeClassHistory(const std::string& out, const std::vector<ClassFigures>& history) {
    std::string text;
    for (const ClassFigures& f : history) text += toJson(f).dump() + "\n";
    writeFileAtomically(out + "/history.jsonl", text);
}

std::string classHistoryHtml(const std::vector<ClassFigures>& history) {
    if (history.empty())
        return "<p>No batch has finished yet: each one that does adds a row here.</p>\n";
    std::ostringstream html;
    if (history.size() >= 2)
        html << chart(history);
    else
        html << "<p>One batch so far: the chart begins with the next.</p>\n";
    html << "<table><tr><th>batch finished (UTC)</th><th>graded</th><th>mean total</th>";
    for (Lab lab : AllLabs) html << "<th>" << labName(lab) << ": mean, correct</th>";
    html << "</tr>\n";
    for (const ClassFigures& f : history) {
        html << "<tr><td>" << escapeXml(f.at) << "</td><td>" << f.graded << " of " << f.submissions
             << "</td><td>" << percent(f.meanTotal) << "</td>";
        for (Lab lab : AllLabs) {
            const std::string name(labName(lab));
            html << "<td>"
                 << (f.labMean.count(name)
                         ? percent(f.labMean.at(name)) + ", " + percent(f.labCorrectness.at(name))
                         : std::string())
                 << "</td>";
        }
        html << "</tr>\n";
    }
    return html.str() + "</table>\n";
}

} // namespace pathlab::grader
