#pragma once
/// What a correct lab's image should average to, region by region, and how noisy a correct lab
/// is: measured from the reference solutions, stored in grader/references/ or made on the fly.

#include "checks/rubric.h"
#include "common/by_lab.h"
#include "isolation/render_run.h"

#include "pathlab/support/input_error.h"

#include <functional>
#include <string>
#include <vector>

namespace pathlab::grader {

/// The expected region means (flat [region][channel], see regionMeans) and their standard errors.
struct Expectation {
    std::string solution; ///< which reference solution measured it
    int seeds = 0, spp = 0;
    std::vector<double> mean, standardError;
    std::vector<float> image; ///< the mean image, for the reports' pictures
};

/// Everything the grader compares one scene with.
struct SceneReference {
    std::string scene; ///< name, e.g. "furnace"
    /// What it was measured from: a stored or cached reference whose hashes or kit version
    /// differ from the scene's and rubric's now is stale (loadReference).
    std::string kitVersion;
    std::string sceneFilesHash; ///< scene_files.h
    std::string parametersHash; ///< referenceParametersHash
    int width = 0, height = 0, tiles = 0, maxDepth = 0;
    float continueProb = 0;
    Expectation depthLimited; ///< labs 1-3, at maxDepth
    Expectation unbiased;     ///< lab 4
    ByLab<double>
        noise; ///< each lab's solution's trimmedSampleVariance at the rubric's seeds and spp
    int noiseSeeds = 0; ///< the seeds and spp (by lab) the noise was measured at
    ByLab<int> noiseSpp;
    /// Each lab's solution's bounce rays per sample in those renders: what a lab whose image
    /// comes from tracing paths traces too (path_evidence.h). Not known in a reference made
    /// before they were kept.
    ByLab<double> bounceRays;
    bool bounceRaysKnown = false;

    const Expectation& forLab(Lab lab) const {
        return isDepthLimited(lab) ? depthLimited : unbiased;
    }
};

/// Called with (done, total) as reference renders finish, for a progress bar.
using Progress = std::function<void(int, int)>;

/// A fingerprint of the rubric's settings that decide what a correct lab's image averages to:
/// image size, tiles, max_depth, continue_prob. (Seeds and samples per pixel change only how
/// precisely it is known; the noise figures' are recorded apart: noiseSeeds, noiseSpp.)
std::string referenceParametersHash(const Rubric& rubric);

/// A stored reference made from other scene files, rubric settings or kit version than now.
struct StaleReference : InputError {
    using InputError::InputError;
};

/// A reference with its header filled in for `rubric`'s sizes and these parameters, and no
/// expectations yet.
SceneReference referenceHeader(const std::string& scene, const Rubric& rubric, int maxDepth,
                               float continueProb);

/// The expectation of a scene whose every region averages to `value`, known exactly (an analytic
/// furnace): no standard error. `formula` says where the value comes from.
Expectation analyticExpectation(const Rubric& rubric, double value, const std::string& formula);

/// Measures a scene's reference with the reference solutions `solution` runs.
SceneReference measureReference(const LabRunner& solution, const std::string& scenePath,
                                const Rubric& rubric, int seeds, int sppFactor,
                                const std::string& scratch, const Progress& progress);

/// references/NAME.json (+ NAME.depth_limited.exr, NAME.unbiased.exr). Atomic writes.
void saveReference(const std::string& folder, const SceneReference& reference);
/// The reference of the scene at `scenePath` stored in `folder` (under the scene's name).
/// Throws InputError if there is none or it is unreadable, StaleReference (saying what changed)
/// if it was measured from other scene files, rubric settings or kit version than now.
SceneReference loadReference(const std::string& folder, const std::string& scenePath,
                             const Rubric& rubric);

} // namespace pathlab::grader
