#pragma once
/// A submission judged again from what its last grading measured (measurements.json), rendering
/// nothing: a batch does it when only the rubric's points or thresholds changed since.

#include "checks/rubric.h"
#include "commands/batch_selection.h"

#include <string>

namespace pathlab::grader {

/// What a re-score did, for the batch's log and terminal.
struct Rescore {
    bool done = false; ///< false: nothing stored to judge again (then grade it)
    double before = 0, after = 0, maxBefore = 0, maxAfter = 0;
    int fromAttempt = 0;
};

/// Judges `s`'s stored measurements (FOLDER = OUT/submissions/ID) under `rubric`, with the speed
/// check where `speed` (a grading of it without speed has none to judge: not done), the pictures'
/// references from `references`; keeps the earlier grading as an attempt and writes the new one.
Rescore rescoreSubmission(const Rubric& rubric, bool speed, const std::string& references,
                          const Submission& s, const std::string& folder);

} // namespace pathlab::grader
