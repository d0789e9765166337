#pragma once
/// Hidden scenes made from the public ones: the same geometry and camera, with the diffuse
/// colours and the light's emission changed by a seed the instructor keeps. A batch whose
/// instructor keeps no hidden scenes grades on these (rubric: hidden_scenes.variants), so that
/// no answer stored in the student release (the references' means, images and tile means) fits
/// every scene graded: such a lab matches the public scenes and fails the variant.

#include "checks/rubric.h"

#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace pathlab::grader {

/// A number in [0, 1) from `engine`'s next: the engine's numbers are the same on every platform,
/// a standard distribution's are not, and a variant must be the same wherever it is drawn.
double portableUnit(std::mt19937_64& engine);

/// Writes the rubric's hidden_scenes.variants variants into `folder` (made if needed):
/// variant_1.ecs with its .obj and .mtl, and so on, the K-th from the K-th of the rubric's
/// public scenes that are not furnaces (round again when there are more variants than those).
/// The same seed writes the same files, byte for byte. Returns the .ecs paths.
std::vector<std::string> writeSceneVariants(const Rubric& rubric, const std::string& folder,
                                            uint64_t seed);

/// The text of one .mtl with each material's Kd scaled per channel within `reflectance`
/// (by default [0.5, 1], so that no material reflects more than it did) and each emission Ke
/// within `light` (by default [0.6, 1.3]), by `random` (one number in [0, 1) per call). Other
/// lines are kept as they are.
std::string variedMaterials(const std::string& mtl, const std::function<double()>& random,
                            DrawRange reflectance = {0.5, 1.0}, DrawRange light = {0.6, 1.3});

/// A copy of the scene at `ecsPath` in `folder` as `stem`.ecs (its files as stem_NAME), its
/// materials varied as variedMaterials does and its point and directional lights times one
/// factor drawn within `light`. Returns the copy's .ecs path.
std::string writeVariedScene(const std::string& ecsPath, const std::string& folder,
                             const std::string& stem, const std::function<double()>& random,
                             DrawRange reflectance, DrawRange light);

/// A copy of the scene at `ecsPath` in `folder` as `stem`.ecs (its files as stem_NAME), each
/// material's Kd and Ke set to the grey `albedo` and `emission`, the .ecs's comments (which
/// describe the public scene's numbers) left out. Returns the copy's .ecs path.
std::string writeGreyMaterialScene(const std::string& ecsPath, const std::string& folder,
                                   const std::string& stem, double albedo, double emission);

/// `mtl` with every emission Ke times `factor`.
std::string scaledEmission(const std::string& mtl, double factor);

/// A copy of the scene at `ecsPath` in `folder` as `stem`.ecs (its files as stem_NAME), every
/// light times `factor`: each material's Ke and each --pointlight and --dirlight's intensity.
/// A lab that is linear in the light it finds renders it as the scene times `factor`, sample by
/// sample. Returns the copy's .ecs path.
std::string writeScaledLightScene(const std::string& ecsPath, const std::string& folder,
                                  const std::string& stem, double factor);

} // namespace pathlab::grader
