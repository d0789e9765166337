#pragma once
/// Per-student variants (the rubric's "variants" section, variant_settings.h): each student
/// grades on scenes of their own, drawn from the class secret and the student's id, so that no
/// answer one student shares (a furnace's value, an image, a mean) fits another's scenes.
///
/// A variant is an analytic furnace (diffuse walls of albedo a emitting Le, rendered at maxDepth
/// D: its value is known exactly for any of them, so it costs no reference) and, where the
/// rubric names one, a public scene with its materials and light varied, whose reference is
/// measured once per student from the solutions and cached by content as hidden scenes' are.
/// A student's variant folder (writeStudentVariantFolder) holds the scenes, their numbers and the
/// box's reference: the student's release grades on it locally (grader --variant DIR), and the
/// folder names no other student's values.

#include "checks/grader_setup.h"
#include "diagnosis/diagnosis.h"

#include <string>
#include <vector>

namespace pathlab::grader {

/// What a student's variant is drawn as.
struct StudentVariant {
    std::string id;
    FurnaceModel furnace; ///< diffuse walls: reflectance = albedo, emission = Le, maxDepth = D
    /// The seed of the box's materials and light (after the furnace's draws).
    uint64_t boxSeed = 0;
};

/// The class secret: the text of the rubric's variants.secret_file, at least 16 characters;
/// throws InputError saying how to make it when it is missing or too short.
std::string classSecret(const VariantSettings& settings);

/// The variant of the student `id` under `secret`: the same for the same three, every time.
StudentVariant drawStudentVariant(const VariantSettings& settings, const std::string& secret,
                                  const std::string& id);

/// The variant's scenes written into `folder` (furnace.ecs, and box.ecs where the rubric names
/// a box scene, with their files), with the furnace's analytic reference and the box's measured
/// by `solution` (kept in `cache`, and taken from there while the files are unchanged).
std::vector<GradingScene> studentVariantScenes(const Rubric& rubric, const StudentVariant& variant,
                                               const std::string& folder, const LabRunner& solution,
                                               const std::string& scratch,
                                               const std::string& cache);

/// Writes the student's variant folder: the scenes, variant.json (the id, the rubric's hash, the
/// furnace's numbers) and references/ (the box's, from `cache` while it fits). Returns the
/// scenes as studentVariantScenes.
std::vector<GradingScene>
writeStudentVariantFolder(const Rubric& rubric, const StudentVariant& variant,
                          const std::string& folder, const LabRunner& solution,
                          const std::string& scratch, const std::string& cache);

/// The scenes of a variant folder writeStudentVariantFolder wrote, for a local grade; throws
/// InputError when it is not one, or when it was made under another rubric or kit.
std::vector<GradingScene> loadStudentVariantFolder(const Rubric& rubric, const std::string& folder);

} // namespace pathlab::grader
