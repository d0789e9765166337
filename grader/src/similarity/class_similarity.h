#pragma once
/// The similarity report of a graded class: which submissions' files of a lab are alike, the
/// kit's reference solutions among them (similarity.h compares two files).

#include "reports/gradebook.h"

#include <string>
#include <vector>

namespace pathlab::grader {

/// Pairs among the lab files the submissions `ids` handed in (OUT/submissions/ID/submitted/) and
/// the kit's solutions (as "reference solutions"), and with the earlier terms kept in `priorDir`
/// ("": none; prior_terms.h), the kit's stubs left out of every comparison; most alike first.
std::vector<SimilarLabs> similarSubmissions(const std::string& out,
                                            const std::vector<std::string>& ids,
                                            const std::string& priorDir = "");

} // namespace pathlab::grader
