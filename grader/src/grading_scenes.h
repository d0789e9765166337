#pragma once
/// The scenes a grading uses and what each is compared with.

#include "grading.h"

#include <string>
#include <vector>

namespace pathlab::grader {

/// The rubric's public scenes (models/NAME.ecs) with their stored references from
/// `referencesFolder`, then the parameter check's furnace (analytic), then every .ecs in `hiddenFolder` (if given) with a reference measured
/// from the solutions `solution` runs. Measured references are kept in `cacheFolder` (if given)
/// and taken from there when present, so a batch measures each scene once. A public scene
/// without a stored reference is measured too, with a note in `notes`.
std::vector<GradingScene> gradingScenes(const Rubric& rubric, const std::string& referencesFolder,
                                        const std::string& hiddenFolder,
                                        const std::string& cacheFolder, const LabRunner& solution,
                                        const std::string& scratch, std::vector<std::string>& notes);

} // namespace pathlab::grader
