#pragma once
/// The pages that show two alike lab files side by side, for the instructor reading a cluster of
/// the summary (reports/similarity_clusters.h): OUT/similarity/, beside the gradebook, never in a
/// student's folder.

#include "reports/similarity_clusters.h"

#include <string>

namespace pathlab::grader {

/// Writes the page of each member's nearest pair in `clusters`: the two files' lines in two
/// columns, the lines the other file has too (whitespace ignored) marked. A submission's file is
/// OUT/submissions/ID/submitted/FILE; "reference solutions" is the kit's solutions/FILE.
void writeSideBySidePages(const std::string& out, const std::vector<SimilarCluster>& clusters);

} // namespace pathlab::grader
