#pragma once
/// Likely causes of a wrong mean, recognised by the value a bug gives in the furnace.

#include "pathlab/lab_registry.h"

#include <string>

namespace pathlab::grader {

/// The furnace's radiance as a lab with a given bug computes it. A closed sphere of diffuse
/// albedo a emitting Le = 1; see tests/estimators/furnace_test.cpp for the correct series.
struct FurnaceModel {
    double albedo = 0.5;
    int maxDepth = 3;
    double continueProb = 0.8;
};

/// The bug whose furnace value best explains `observed` (± `standardError`) for this lab, as a
/// sentence for the student; empty when none is close.
std::string diagnoseFurnace(Lab lab, const FurnaceModel& model, double observed,
                            double standardError);

/// The correct furnace value for the lab.
double correctFurnaceValue(Lab lab, const FurnaceModel& model);

} // namespace pathlab::grader
