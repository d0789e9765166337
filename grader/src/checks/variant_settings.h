#pragma once
/// The rubric's per-student variants (its section "variants"): whether each student grades on
/// scenes of their own, and the ranges those scenes are drawn from (student_variant.h). The
/// secret's file is named here; its text is not part of the rubric's hash but of the scenes'
/// (grading_scenes.h), so that a new secret regrades the class as new scenes do.

#include <nlohmann/json.hpp>

#include <string>

namespace pathlab::grader {

/// A closed interval a value is drawn from, uniformly.
struct DrawRange {
    double low = 0, high = 0;
};

struct VariantSettings {
    bool perStudent = false;
    /// Absolute; its text and a student's id seed the student's variant. "" in a student
    /// release's rubric, which grades on the student's variant folder instead.
    std::string secretFile;
    // The analytic furnace each student grades on: diffuse walls of albedo a emitting Le,
    // rendered at maxDepth D (a whole number, both ends included).
    DrawRange albedo{0.3, 0.8};
    DrawRange emission{0.5, 2.0};
    DrawRange maxDepth{2, 6};
    /// A public scene of models/ each student grades on with its materials and light varied,
    /// one reference measured per student; "" for none (the furnace alone costs no reference).
    std::string boxScene;
    DrawRange reflectance{0.5, 1.0}; ///< the factor on each Kd value
    DrawRange light{0.6, 1.3};       ///< the factor on each Ke value
};

/// Reads the rubric's "variants" section (`section`; null for none) of the rubric at
/// `rubricPath`, the secret's file relative to it; throws InputError naming what is wrong.
VariantSettings readVariantSettings(const nlohmann::json& section, const std::string& rubricPath);

} // namespace pathlab::grader
