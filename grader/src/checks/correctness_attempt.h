#pragma once
/// What one attempt of the correctness check found over all scenes, as correctness_check.cpp
/// builds it and rejection_explanation.h explains it.

#include "checks/check_result.h"
#include "checks/hypothesis_tests.h"
#include "checks/path_length.h"
#include "checks/reproducibility_check.h"
#include "checks/seed_spread.h"

#include <string>
#include <vector>

namespace pathlab::grader {

/// One scene's renders against its reference, region by region: the whole image's three
/// channels, then each tile's.
struct Comparison {
    std::vector<double> t, p;
    std::vector<MeanEstimate> observed;
};

/// Why a lab's renders could not be compared at all.
struct RunFailure {
    std::string text, kind;
    bool empty() const { return text.empty(); }
};

/// What one attempt over all scenes found: on rejection, the details and diagnosis.
struct Attempt {
    bool passed = false;
    std::vector<std::string> details, hiddenDetails;
    std::vector<std::string> notes; ///< said whatever the verdict (RenderResult::outputNote)
    std::string diagnosis;
    RunFailure failure;
    double noise = -1; ///< see CorrectnessOutcome
    std::vector<LabGrade::Pictures> pictures;
    /// The first seed's image of the noise scene (or of the first scene), rendered again by the
    /// reproducibility check.
    SeedImage firstImage;
    /// Every seed's image of the speed scene, which the speed check's timed runs must render
    /// again, bit for bit.
    std::vector<std::vector<float>> speedSceneImages;
};

/// What the renders of every scene leave for the verdict.
struct SceneComparisons {
    std::vector<Comparison> scenes;    ///< one per scene, in the setup's order
    std::vector<std::string> untraced; ///< per scene: missingPathEvidence, "" where it is traced
    std::vector<double> allP;          ///< every scene's regions' p, in a row
    std::vector<PathLengthObservation> pathLengths; ///< lab 4 in the diffuse furnaces
    std::vector<SeedSpread> spreads;                ///< per scene: seed_spread.h
    bool stepsOpen = false;                         ///< see SceneRuns
};

} // namespace pathlab::grader
