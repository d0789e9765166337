#include "reports/sweep_figures.h"

#include "pathlab/support/parse_number.h"

#include <algorithm>
#include <filesystem>
#include <fstream>

namespace pathlab::grader {

namespace {

namespace fs = std::filesystem;

std::vector<std::string> csvFields(const std::string& line) {
    std::vector<std::string> fields;
    for (std::string_view field : splitAt(line, ',')) fields.emplace_back(field);
    return fields;
}

/// The rows of sweep.csv and the value of the most efficient one. sweep.py writes plain numbers
/// (no quotes, no commas inside a field).
void readTable(const fs::path& csv, SweepFigure& sweep) {
    std::ifstream in(csv);
    std::string line;
    if (!std::getline(in, line)) return;
    const std::vector<std::string> header = csvFields(line);
    if (!header.empty()) sweep.parameter = header[0];
    if (sweep.parameter == "continue_prob") sweep.parameter = "continueProb";
    if (sweep.parameter == "max_depth") sweep.parameter = "maxDepth";
    const auto column = std::find(header.begin(), header.end(), "efficiency");
    const size_t efficiency = static_cast<size_t>(column - header.begin());
    float best = -1;
    while (std::getline(in, line)) {
        if (line.empty()) continue;
        ++sweep.values;
        const std::vector<std::string> row = csvFields(line);
        if (column == header.end() || row.size() <= efficiency) continue;
        const std::optional<float> value = parseFloat(row[efficiency]);
        if (value && *value > best) best = *value, sweep.mostEfficient = row[0];
    }
}

} // namespace

std::vector<SweepFigure> findSweeps(const std::string& folder, const std::string& reportFolder) {
    std::vector<SweepFigure> sweeps;
    std::error_code error;
    if (!fs::is_directory(folder, error)) return sweeps;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder, error)) {
        const fs::path plot = entry.path() / "sweep.png", csv = entry.path() / "sweep.csv";
        if (!fs::is_regular_file(plot, error) || !fs::is_regular_file(csv, error)) continue;
        SweepFigure sweep;
        sweep.name = entry.path().filename().string();
        sweep.lab = sweep.name.substr(0, sweep.name.find('-'));
        sweep.plot = fs::proximate(plot, reportFolder, error).generic_string();
        sweep.table = fs::proximate(csv, reportFolder, error).generic_string();
        readTable(csv, sweep);
        sweeps.push_back(sweep);
    }
    std::sort(sweeps.begin(), sweeps.end(),
              [](const SweepFigure& a, const SweepFigure& b) { return a.name < b.name; });
    return sweeps;
}

std::string findConvergencePlot(const std::string& folder, const std::string& reportFolder) {
    std::error_code error;
    const fs::path plot = fs::path(folder) / "convergence.png";
    if (!fs::is_regular_file(plot, error) ||
        !fs::is_regular_file(fs::path(folder) / "convergence.csv", error))
        return "";
    return fs::proximate(plot, reportFolder, error).generic_string();
}

} // namespace pathlab::grader
