#pragma once
/// Each render's time limit, scaled to how fast this machine runs now.
///
/// The rubric's limit (30 s) is about fifteen times what the slowest grading render takes on an
/// idle machine. On a busy one (a class graded two at a time, a build beside it) every render is
/// slower, and a fixed limit would turn a correct but slow-running lab into "did not finish".
/// So the limit grows with the reference's own start-up render, timed now, over the same render
/// timed when the references were made (grader/references/lab_figures.json).

#include <string>

namespace pathlab::grader {

/// The most the limit grows: beyond that, something other than load is wrong.
constexpr double MaxSlowness = 10;

/// `rubricSeconds` × (startupNow / startupStored), from 1 to MaxSlowness times `rubricSeconds`;
/// `rubricSeconds` when either time is unknown (0).
double scaledTimeLimit(double rubricSeconds, double startupNow, double startupStored);

/// For the report: "renders run 2.3 times slower here now than when the references were made:
/// each render may take 69 s (the rubric's 30 s × 2.3)".
std::string timeLimitNote(double rubricSeconds, double scaledSeconds);

} // namespace pathlab::grader
