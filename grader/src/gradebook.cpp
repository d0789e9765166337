#include "gradebook.h"

#include "reports.h"

#include "pathlab/lab_registry.h"
#include "pathlab/render_stats.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

namespace pathlab::grader {

namespace {

std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\n") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

std::string number(double value) {
    std::ostringstream out;
    out << value;
    return out.str();
}

std::string csv(const std::vector<GradebookEntry>& entries) {
    std::string text = "id";
    for (Lab lab : AllLabs) text += "," + std::string(labName(lab));
    text += ",total,max_total,status\n";
    for (const GradebookEntry& e : entries) {
        text += csvField(e.id);
        if (e.result.is_null()) {
            for (size_t i = 0; i < AllLabs.size() + 2; ++i) text += ",";
            text += "," + csvField("not graded: " + e.problem) + "\n";
            continue;
        }
        for (Lab lab : AllLabs) text += "," + number(e.result["labs"][std::string(labName(lab))].value("score", 0.0));
        text += "," + number(e.result.value("score", 0.0)) + "," + number(e.result.value("max_score", 0.0));
        text += "," + csvField(e.result.value("status", "")) + "\n";
    }
    return text;
}

/// A bar chart of the totals in tenths of the maximum, as inline SVG.
std::string histogram(const std::vector<GradebookEntry>& entries) {
    std::array<int, 10> bins{};
    for (const GradebookEntry& e : entries) {
        if (e.result.is_null()) continue;
        const double max = e.result.value("max_score", 0.0);
        const double fraction = max > 0 ? e.result.value("score", 0.0) / max : 0;
        ++bins[std::min(9, static_cast<int>(std::floor(fraction * 10)))];
    }
    const int tallest = std::max(1, *std::max_element(bins.begin(), bins.end()));
    std::ostringstream svg;
    svg << "<svg width=\"520\" height=\"200\" xmlns=\"http://www.w3.org/2000/svg\" "
           "font-family=\"sans-serif\" font-size=\"11\">\n";
    for (int i = 0; i < 10; ++i) {
        const int h = 150 * bins[i] / tallest, x = 10 + 50 * i;
        svg << "<rect x=\"" << x << "\" y=\"" << 160 - h << "\" width=\"44\" height=\"" << h
            << "\" fill=\"#4a7ab5\"/>\n<text x=\"" << x + 22 << "\" y=\"" << 155 - h
            << "\" text-anchor=\"middle\">" << bins[i] << "</text>\n<text x=\"" << x + 22
            << "\" y=\"178\" text-anchor=\"middle\">" << 10 * i << "-" << (i == 9 ? 100 : 10 * i + 9)
            << "%</text>\n";
    }
    svg << "<text x=\"260\" y=\"196\" text-anchor=\"middle\">total score, % of the maximum</text></svg>\n";
    return svg.str();
}

std::string summaryPage(const std::vector<GradebookEntry>& entries) {
    int graded = 0;
    double sum = 0;
    std::map<std::pair<std::string, std::string>, int> diagnoses; // (lab, diagnosis) -> count
    for (const GradebookEntry& e : entries) {
        if (e.result.is_null()) continue;
        ++graded;
        const double max = e.result.value("max_score", 0.0);
        sum += max > 0 ? e.result.value("score", 0.0) / max : 0;
        for (const auto& d : e.result.value("diagnoses", nlohmann::json::array()))
            if (d.value("check", "") == "correctness" || d.value("diagnosis", "") == "too noisy" ||
                d.value("diagnosis", "") == "too slow")
                ++diagnoses[{d.value("lab", ""), d.value("diagnosis", "")}];
    }
    std::vector<std::pair<int, std::pair<std::string, std::string>>> common;
    for (const auto& [key, count] : diagnoses) common.push_back({count, key});
    std::sort(common.begin(), common.end(), [](const auto& a, const auto& b) {
        return a.first != b.first ? a.first > b.first : a.second < b.second;
    });

    std::ostringstream html;
    html << "<!doctype html><html><head><meta charset=\"utf-8\"><title>PathLab batch</title><style>"
            "body{font-family:sans-serif;max-width:1100px;margin:auto}td,th{padding:3px 10px;"
            "text-align:left}tr:nth-child(even){background:#f4f4f4}</style></head><body>\n"
         << "<h1>PathLab batch: " << graded << " of " << entries.size() << " submissions graded</h1>\n";
    if (graded > 0) html << "<p>Mean total: " << number(std::round(1000 * sum / graded) / 10) << "% of the maximum.</p>\n";
    html << "<h2>Scores</h2>\n" << histogram(entries) << "<h2>Most common diagnoses</h2>\n"
         << "<table><tr><th>submissions</th><th>lab</th><th>diagnosis</th></tr>\n";
    for (const auto& [count, key] : common)
        html << "<tr><td>" << count << "</td><td>" << escapeXml(key.first) << "</td><td>"
             << escapeXml(key.second) << "</td></tr>\n";
    html << "</table>\n<h2>Submissions</h2>\n<table><tr><th>id</th><th>score</th><th>status</th></tr>\n";
    for (const GradebookEntry& e : entries) {
        const std::string link = "submissions/" + e.id + "/index.html";
        if (e.result.is_null())
            html << "<tr><td>" << escapeXml(e.id) << "</td><td></td><td>not graded: "
                 << escapeXml(e.problem) << "</td></tr>\n";
        else
            html << "<tr><td><a href=\"" << escapeXml(link) << "\">" << escapeXml(e.id)
                 << "</a></td><td>" << number(e.result.value("score", 0.0)) << " / "
                 << number(e.result.value("max_score", 0.0)) << "</td><td>"
                 << escapeXml(e.result.value("status", "")) << "</td></tr>\n";
    }
    html << "</table></body></html>\n";
    return html.str();
}

} // namespace

GradebookEntry readGradebookEntry(const std::string& out, const std::string& id,
                                  const std::string& submission) {
    GradebookEntry entry{id, submission, nullptr, ""};
    std::ifstream in(out + "/submissions/" + id + "/result.json");
    if (!in) {
        entry.problem = "no result (see submissions/" + id + "/grader.log)";
        return entry;
    }
    try {
        entry.result = nlohmann::json::parse(in);
    } catch (const nlohmann::json::exception& e) {
        entry.problem = std::string("its result.json is unreadable: ") + e.what();
    }
    return entry;
}

void writeGradebook(const std::string& out, const std::vector<GradebookEntry>& entries) {
    writeFileAtomically(out + "/gradebook.csv", csv(entries));
    writeFileAtomically(out + "/summary.html", summaryPage(entries));
}

} // namespace pathlab::grader
