#pragma once
/// Earlier terms' submissions for the similarity report (grader batch --prior DIR): a term is
/// kept as the normalised token streams of its lab files (similarity.h's normalisedTokens:
/// names, numbers and literals replaced, comments dropped), never their code, one file per term,
/// DIR/TERM.json. A batch compares this term's files with them, not them among themselves.

#include "similarity/similarity.h"

#include <string>
#include <vector>

namespace pathlab::grader {

/// Writes DIR/TERM.json from the lab files the submissions `ids` of the batch output `out`
/// handed in (OUT/submissions/ID/submitted/); returns how many files it kept. Throws InputError
/// for a term name that is not a plain name.
int keepPriorTerm(const std::string& out, const std::vector<std::string>& ids,
                  const std::string& term, const std::string& dir);

/// Every earlier term's files kept in `dir`, as "TERM/ID" (a slash no submission id has);
/// throws InputError naming a file that is not one keepPriorTerm wrote.
std::vector<SubmittedFile> priorTermFiles(const std::string& dir);

/// Whether `id` names an earlier term's submission ("TERM/ID").
bool isPriorSubmission(const std::string& id);

} // namespace pathlab::grader
