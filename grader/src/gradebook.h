#pragma once
/// A class's results: gradebook.csv (a row per submission) and summary.html (the score
/// histogram and the most common diagnoses), made from the submissions' result.json files.

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace pathlab::grader {

/// One submission's line: its result.json, or for a submission not graded, its id, path and why.
struct GradebookEntry {
    std::string id, submission;
    nlohmann::json result; ///< null when not graded
    std::string problem;   ///< why not graded
};

/// Reads OUT/submissions/ID/result.json; an entry with a problem where there is none.
GradebookEntry readGradebookEntry(const std::string& out, const std::string& id,
                                  const std::string& submission);

/// Writes OUT/gradebook.csv and OUT/summary.html (atomically), rows in the order of `entries`.
void writeGradebook(const std::string& out, const std::vector<GradebookEntry>& entries);

} // namespace pathlab::grader
