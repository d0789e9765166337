#pragma once
/// Likely causes of a wrong image, each naming the step of the lab it is about: recognised by
/// the values known bugs give in the furnaces, or by NaN. Shared by the grader and the lab tests.

#include "diagnosis/diagnosis_table.h"

#include "pathlab/render/lab_registry.h"

#include <optional>
#include <string>
#include <vector>

namespace pathlab::grader {

/// How the walls of a furnace reflect: diffusely (Kd) or as a perfect mirror (Ks).
enum class FurnaceWalls { Diffuse, Mirror };

/// A furnace: a closed sphere whose walls face inward and emit Le = 1, the camera inside (see
/// models/README.md). Its radiance as a lab computes it follows from these few numbers.
struct FurnaceModel {
    FurnaceWalls walls = FurnaceWalls::Diffuse;
    double reflectance = 0.5;  ///< the walls' Kd or Ks, grey
    int maxDepth = 3;          ///< labs 1-3
    double continueProb = 0.8; ///< lab 4
    /// The walls' Le: every term of a lab's radiance, a bug's included, is linear in it.
    double emission = 1;
};

/// The model of a furnace of models/ by scene name ("furnace", "furnace_a08", "mirror_furnace"),
/// rendered with these parameters; none for a scene that is not one of them.
std::optional<FurnaceModel> furnaceModel(const std::string& scene, int maxDepth,
                                         double continueProb);

/// The furnace's radiance as a correct lab computes it.
double correctFurnaceValue(Lab lab, const FurnaceModel& model);

/// That value's formula with its numbers, e.g. "Le·(1 − a^(D+2))/(1 − a) with Le = 1, a = 0.5,
/// D = 3".
std::string furnaceFormula(Lab lab, const FurnaceModel& model);

/// What a lab rendered in one furnace: the image mean and its standard error.
struct FurnaceObservation {
    FurnaceModel model;
    double observed = 0;
    double standardError = 0;
};

/// The known bugs that explain every observation for this lab (each furnace's value within 4
/// standard errors or 1.5% of the bug's) and that some observation tells apart from a correct
/// lab, best first, each as a sentence for the student that names the lab's step
/// ("... (TODO lab3.1)"); empty when none does. One furnace alone may leave several: in the
/// mirror furnace a lab without emission after specular bounces and one without any bounce both
/// give Le; the diffuse furnace tells them apart. `stepsOpen`: whether the lab still reports a
/// TODO step when it runs (a sentence about open steps fits only such a lab).
std::vector<std::string>
likelyFurnaceCauses(Lab lab, const std::vector<FurnaceObservation>& observations, bool stepsOpen);

/// Why a lab's image holds NaN or infinite values, as far as the lab tells, naming its step.
std::string likelyNonfiniteCause(Lab lab);

/// What a wrong image of models/mixed_surfaces means, when the furnaces and the refraction check
/// accept the lab: a diffuse direction drawn from part of the hemisphere, naming the step.
std::string likelyDirectionCause(Lab lab);

/// One colour channel's observed/expected over a whole image: its confidence interval.
struct ChannelInterval {
    double low = 1, high = 1;
};

/// Whether one channel is surely too bright (its interval above 1) and another surely too dark.
/// On models/mixed_surfaces, whose two-component materials are red diffuse beside a teal mirror
/// or cyan glass, each channel's light comes mostly through one component: a lab that divides by
/// another probability than the one it picked with weighs one component too much and the other
/// too little, so red and blue go opposite ways, while a wrong diffuse direction changes the
/// light every channel gathers diffusely the same way.
bool channelsOffOppositeWays(const std::vector<ChannelInterval>& channels);

/// What mixed_surfaces' channels off in opposite ways mean, when the furnaces and the refraction
/// check accept the lab: the probability divided by is not the one picked with, naming the step;
/// empty for lab 1, which picks nothing.
std::string likelyPickDivideCause(Lab lab);

/// What a wrong view through a glass sphere means, when the furnaces (which hold no glass)
/// accept the lab, naming its step.
std::string likelyRefractionCause(Lab lab);

/// The furnace's radiance as a lab with `bug` renders it (`depth`: where the bug is
/// perObservedDepth, the depth it renders at), to check that the diagnosis finds each bug.
double furnaceValueWithBug(Lab lab, const FurnaceModel& model, const KnownBug& bug, int depth = -1);

} // namespace pathlab::grader
