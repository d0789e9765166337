#include "similarity/side_by_side.h"

#include "reports/page_style.h"
#include "similarity/prior_terms.h"
#include "reports/reports.h"

#include "pathlab/render/lab_registry.h"
#include "pathlab/support/whole_file.h"

#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace pathlab::grader {

namespace fs = std::filesystem;

namespace {

/// The id's file of `lab`; "" if it cannot be read.
std::string labFileOf(const std::string& out, const std::string& id, const std::string& lab) {
    const std::optional<Lab> known = labFromName(lab);
    if (!known) return "";
    if (isPriorSubmission(id))
        return "(an earlier term's submission: PathLab kept its normalised tokens only, not its "
               "code; the similarity is of those)";
    const std::string file = labFileName(*known);
    const fs::path path = id == KitSolutions
                              ? fs::path(PATHLAB_GRADER_DIR).parent_path() / "solutions" / file
                              : fs::path(out) / "submissions" / id / "submitted" / file;
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::string squeezed(const std::string& line) {
    std::string text;
    for (char c : line)
        if (!std::isspace(static_cast<unsigned char>(c))) text += c;
    return text;
}

std::vector<std::string> linesOf(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

/// One file's column: its lines, those the other file has too marked.
std::string column(const std::string& id, const std::vector<std::string>& lines,
                   const std::set<std::string>& other) {
    std::ostringstream html;
    html << "<td><h2>" << escapeXml(id) << "</h2><pre>";
    for (const std::string& line : lines) {
        const std::string key = squeezed(line);
        const bool shared = !key.empty() && other.count(key);
        html << (shared ? "<span class=\"same\">" : "<span>") << escapeXml(line) << "</span>\n";
    }
    return html.str() + "</pre></td>";
}

std::string page(const SimilarLabs& pair, const std::string& first, const std::string& second) {
    const std::vector<std::string> a = linesOf(first), b = linesOf(second);
    std::set<std::string> inA, inB;
    for (const std::string& line : a) inA.insert(squeezed(line));
    for (const std::string& line : b) inB.insert(squeezed(line));
    std::ostringstream html;
    html << "<!doctype html><html><head><meta charset=\"utf-8\"><title>" << escapeXml(pair.lab)
         << ": " << escapeXml(pair.first) << " and " << escapeXml(pair.second) << "</title><style>"
         << pageStyle()
         << " .same{background:#fde2a7} td{vertical-align:top;width:50%} pre{white-space:pre-wrap}"
         << "</style></head><body>\n<h1>" << escapeXml(pair.lab) << ": " << escapeXml(pair.first)
         << " and " << escapeXml(pair.second) << ", " << std::lround(100 * pair.similarity)
         << "% alike</h1>\n<p>Marked: the lines the other file has too, whitespace ignored. The "
            "similarity figure compares token sequences with names and numbers ignored, so a "
            "renamed copy is alike though few lines are marked. A hint to read, never a "
            "verdict.</p>\n<table><tr>"
         << column(pair.first, a, inB) << column(pair.second, b, inA)
         << "</tr></table></body></html>\n";
    return html.str();
}

} // namespace

void writeSideBySidePages(const std::string& out, const std::vector<SimilarCluster>& clusters) {
    std::set<std::string> written;
    for (const SimilarCluster& c : clusters)
        for (const SimilarCluster::Member& m : c.members) {
            const std::string name = sideBySidePage(m.nearest);
            if (!written.insert(name).second) continue;
            fs::create_directories(fs::path(out) / "similarity");
            writeFileAtomically(out + "/" + name,
                                page(m.nearest, labFileOf(out, m.nearest.first, c.lab),
                                     labFileOf(out, m.nearest.second, c.lab)));
        }
}

} // namespace pathlab::grader
