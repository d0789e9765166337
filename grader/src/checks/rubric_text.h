#pragma once
/// The rubric in words (`grader rubric`): what the handouts and READMEs point to instead of
/// quoting numbers that go stale when an instructor edits grader/rubric.json.

#include "checks/rubric.h"

#include <string>

namespace pathlab::grader {

/// Every setting that decides a grade, each with what it means. `hiddenScenes` is how many hidden
/// scenes the grader finds (the instructor's grader/hidden_scenes/; 0 in a student's kit).
std::string rubricText(const Rubric& rubric, const std::string& rubricPath, int hiddenScenes);

/// In a student release packaged with the instructor's rubric (make student-release RUBRIC=...,
/// which writes release.json beside rubric.json): which rubric the release carries, and a note
/// when the rubric read now is not that one (edited since). "" elsewhere.
std::string releasedRubricNote(const Rubric& rubric, const std::string& rubricPath);

} // namespace pathlab::grader
