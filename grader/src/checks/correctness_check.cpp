#include "checks/correctness_check.h"

#include "checks/correctness_attempt.h"
#include "checks/correctness_renders.h"
#include "checks/hypothesis_tests.h"
#include "checks/light_linearity.h"
#include "checks/number_text.h"
#include "checks/path_evidence.h"
#include "checks/rejection_explanation.h"
#include "checks/path_length.h"
#include "checks/rays_per_sample.h"
#include "checks/reproducibility_check.h"
#include "checks/run_limits.h"
#include "checks/seed_spread.h"
#include "checks/seed_variance.h"
#include "checks/worst_tile_replay.h"
#include "diagnosis/diagnosis.h"

#include "pathlab/support/input_error.h"
#include "pathlab/todo.h"

#include <algorithm>
#include <cmath>

namespace pathlab::grader {

namespace {

/// k independent renders of one lab on one scene.
struct SceneRuns {
    std::vector<std::vector<double>> regionValues; ///< [statistic][seed]
    std::vector<std::vector<float>> images;        ///< one per seed
    RaysPerSample rays;                            ///< over all seeds (the lab's own counts)
    bool stepsOpen = false; ///< the lab reported a TODO step not written yet (pathlab/todo.h)
    std::string failure, failureKind; ///< see RenderResult
    std::string outputNote;           ///< see RenderResult

    /// The mean of the seeds' images, for the reports' pictures.
    std::vector<float> meanImage() const {
        std::vector<float> mean(images.front().size(), 0.0f);
        for (const auto& image : images)
            for (size_t i = 0; i < image.size(); ++i)
                mean[i] += image[i] / static_cast<float>(images.size());
        return mean;
    }
};

SceneRuns renderSeeds(const GraderSetup& setup, const GradingScene& scene, Lab lab,
                      uint64_t seedBase) {
    const Rubric& r = setup.rubric;
    SceneRuns runs;
    const int spp = r.forLab(lab).correctnessSpp;
    const RenderRequest request = correctnessRequest(setup, scene, lab, seedBase, setup.student);
    const RenderResult result = renderLab(request, limitsOf(setup));
    runs.outputNote = result.outputNote;
    if (!result.ok) {
        runs.failure = result.failure;
        runs.failureKind = result.failureKind;
        return runs;
    }
    runs.stepsOpen = result.process.output.find(TodoNotDoneWords) != std::string::npos;
    RayCounters rays;
    for (const RenderedImage& rendered : result.images) {
        rays += rendered.rays;
        const std::vector<double> means =
            regionMeans(rendered.rgb, result.width, result.height, r.tiles);
        if (runs.regionValues.empty()) runs.regionValues.resize(means.size());
        for (size_t i = 0; i < means.size(); ++i) runs.regionValues[i].push_back(means[i]);
        runs.images.push_back(rendered.rgb);
    }
    runs.rays = raysPerSample(rays, static_cast<double>(r.width) * r.height * spp * r.seeds);
    return runs;
}

Comparison compare(const SceneRuns& runs, const Expectation& expected, int seeds) {
    Comparison c;
    for (size_t i = 0; i < runs.regionValues.size(); ++i) {
        const MeanEstimate m = batchMean(runs.regionValues[i]);
        // A region that every path sees alike (the blue of the refraction check, 0.2 through
        // the glass wherever it leads) has no sampling noise at all; there the means still
        // differ by float rounding, which grows with spp. That rounding, a few parts in 1e7
        // of a float accumulation, is bounded by a relative floor far below any bug's effect.
        const double rounding = floatRoundingFloor * std::fabs(expected.mean[i]);
        const double se =
            std::sqrt(m.standardError * m.standardError +
                      expected.standardError[i] * expected.standardError[i] + rounding * rounding);
        const double t = se > 0 ? (m.mean - expected.mean[i]) / se
                                : (m.mean == expected.mean[i] ? 0.0 : INFINITY);
        c.t.push_back(t);
        c.p.push_back(studentTwoSidedP(t, seeds - 1));
        c.observed.push_back(m);
    }
    return c;
}

/// What the renders of `runs` show of paths, beside the reference's on the same scene.
PathEvidence pathEvidence(const GraderSetup& setup, const GradingScene& scene, Lab lab,
                          const SceneRuns& runs) {
    const Rubric& r = setup.rubric;
    const SceneReference& ref = scene.reference;
    const Expectation& expected = ref.forLab(lab);
    PathEvidence e;
    // Against the least any lab's reference solution shows on the scene, not this lab's own: a
    // valid variant of lab 2 that picks among the non-black components only is as quiet as
    // lab 1 (and deterministic in the mirror furnace), and lab 2's own traces the fewest bounces.
    e.variance = trimmedSampleVariance(runs.images, r.forLab(lab).correctnessSpp);
    e.referenceVariance = *std::min_element(ref.noise.begin(), ref.noise.end());
    e.bounceRays = runs.rays.bounce;
    if (ref.bounceRaysKnown)
        e.referenceBounceRays = *std::min_element(ref.bounceRays.begin(), ref.bounceRays.end());
    e.meanImage = runs.meanImage();
    e.referenceImage = expected.image;
    e.width = r.width;
    e.height = r.height;
    e.tiles = r.tiles;
    // The reference image is the mean of the solution that measured it (importance's or
    // roulette's, expectation.cpp) over its seeds and spp.
    const double samples = double(expected.spp) * expected.seeds;
    e.referenceNoise =
        samples > 0 ? ref.noise[isDepthLimited(lab) ? Lab::Importance : Lab::Roulette] / samples
                    : 0;
    return e;
}

/// Renders every scene and compares it with its reference, keeping in `attempt` the noise figure,
/// the first image and the public scenes' pictures; a scene whose renders fail ends it, with
/// `attempt.failure` saying so.
SceneComparisons renderAndCompare(const GraderSetup& setup, Lab lab, uint64_t seedBase,
                                  Attempt& attempt) {
    const Rubric& r = setup.rubric;
    SceneComparisons found;
    for (const GradingScene& scene : setup.scenes) {
        const SceneRuns runs = renderSeeds(setup, scene, lab, seedBase);
        if (!runs.failure.empty()) {
            attempt.failure = {"on " + scene.name + " the lab " +
                                   failureAsShown(runs.failure, runs.failureKind, scene),
                               runs.failureKind};
            return found;
        }
        found.stepsOpen = found.stepsOpen || runs.stepsOpen;
        if (!scene.hidden && !runs.outputNote.empty() &&
            std::find(attempt.notes.begin(), attempt.notes.end(), runs.outputNote) ==
                attempt.notes.end())
            attempt.notes.push_back(runs.outputNote);
        // The noise figure and the image rendered again come from a public scene: the noise
        // scene, else the first.
        if (!scene.hidden && (scene.reference.scene == r.noiseScene || attempt.noise < 0))
            attempt.noise = trimmedSampleVariance(runs.images, r.forLab(lab).correctnessSpp);
        if (!scene.hidden && (scene.reference.scene == r.noiseScene || !attempt.firstImage.scene))
            attempt.firstImage = {&scene, seedBase, setup.threads, runs.images.front()};
        if (&scene == speedScene(setup)) attempt.speedSceneImages = runs.images;
        if (!isDepthLimited(lab) && scene.furnace && scene.furnace->walls == FurnaceWalls::Diffuse)
            found.pathLengths.push_back({scene.furnace->continueProb, runs.rays.bounce});
        found.scenes.push_back(compare(runs, scene.reference.forLab(lab), r.seeds));
        found.spreads.push_back(seedSpread(runs.images, r.width, r.height, r.tiles));
        found.untraced.push_back(missingPathEvidence(pathEvidence(setup, scene, lab, runs)));
        found.allP.insert(found.allP.end(), found.scenes.back().p.begin(),
                          found.scenes.back().p.end());
        if (scene.hidden) continue; // its images are the instructor's
        LabGrade::Pictures pictures{
            scene.name, r.width, r.height, {}, scene.reference.forLab(lab).image, {}, {}, 0};
        pictures.student = runs.meanImage();
        pictures.regionT = found.scenes.back().t;
        pictures.regionP = found.scenes.back().p;
        pictures.tilesPerSide = r.tiles;
        attempt.pictures.push_back(std::move(pictures));
    }
    return found;
}

/// One attempt of the correctness check over all scenes. `noise`: the figure of an earlier
/// attempt (-1: none), kept where this one does not reach the noise scene.
Attempt correctnessAttempt(const GraderSetup& setup, Lab lab, uint64_t seedBase, double noise) {
    Attempt attempt;
    attempt.noise = noise;
    const SceneComparisons found = renderAndCompare(setup, lab, seedBase, attempt);
    if (!attempt.failure.empty()) return attempt;
    const std::vector<bool> rejected = holmRejections(found.allP, setup.rubric.alpha);
    // A lab 4 that continues with a constant of its own is unbiased, but not lab 4: its paths
    // tell (path_length.h). That cause wins over any the images suggest.
    const std::string ignored = ignoredContinueProb(found.pathLengths);
    if (!ignored.empty()) {
        attempt.details.push_back("likely cause: " + ignored);
        attempt.diagnosis = causeName(ignored);
        return attempt;
    }
    // A comparison that could not have found a difference says nothing: a lab too noisy to
    // judge is not taken as matching, whatever its t-tests say.
    if (explainTooNoisy(setup, found, attempt)) return attempt;
    // Means that match from images that do not come from paths are told before anything a
    // hidden scene says: a table of the public scenes' answers fits no hidden scene either. A lab
    // whose public scenes differ is told why they differ instead (the stub traces no bounce).
    if (!publicSceneRejected(setup, found, rejected) && explainUntraced(setup, found, attempt))
        return attempt;
    if (!anyRejected(rejected)) {
        if (const std::string note = pathLengthNote(found.pathLengths); !note.empty())
            attempt.details.push_back(note);
        for (const GradingScene& scene : setup.scenes)
            if (scene.hidden) attempt.hiddenDetails.push_back(scene.name + HiddenSceneMatches);
        attempt.passed = true;
        return attempt;
    }
    explainRejection(setup, lab, found, rejected, seedBase, attempt);
    return attempt;
}

/// ", and the furnace's analytic value at maxDepth 5" where the grading has a parameter check.
std::string parameterCheckText(const GraderSetup& setup, Lab lab) {
    for (const GradingScene& scene : setup.scenes) {
        if (!scene.parameters) continue;
        return isDepthLimited(lab)
                   ? ", and the furnace's analytic value at maxDepth " +
                         std::to_string(scene.parameters->maxDepth)
                   : ", at continueProb " + significant(scene.parameters->continueProb, 2) +
                         " as at " + significant(setup.rubric.continueProb, 2);
    }
    return "";
}

} // namespace

CorrectnessOutcome checkCorrectness(const GraderSetup& setup, Lab lab) {
    CorrectnessOutcome outcome;
    CheckResult& check = outcome.check;
    check.kind = CheckKind::Correctness;
    check.maxScore = setup.rubric.forLab(lab).points.correctness;
    Attempt attempt = correctnessAttempt(setup, lab, firstSeedBase(setup), -1);
    outcome.speedSceneImages = attempt.speedSceneImages;
    if (!attempt.passed && attempt.failure.empty()) {
        // A rejection at alpha happens to correct labs too, rarely: only a second rejection on
        // fresh seeds counts. A retry whose renders fail keeps the first attempt's words.
        Attempt retry = correctnessAttempt(setup, lab, firstSeedBase(setup) + 500, attempt.noise);
        if (!retry.failure.empty()) {
            retry.details = std::move(attempt.details);
            retry.hiddenDetails = std::move(attempt.hiddenDetails);
            retry.diagnosis = std::move(attempt.diagnosis);
        }
        attempt = std::move(retry);
    }
    // The same seed must give the same image: a certain finding, where the statistics' causes
    // are only likely, so it comes first and fails the check on its own.
    Reproducibility reproducibility;
    if (attempt.failure.empty() && attempt.firstImage.scene)
        reproducibility = checkReproducibility(setup, lab, attempt.firstImage);
    check.passed = attempt.passed && reproducibility.reproducible;
    outcome.noise = attempt.noise;
    outcome.pictures = std::move(attempt.pictures);
    check.score = check.passed ? check.maxScore : 0;
    const std::string expected =
        isDepthLimited(lab)
            ? "the depth-limited image (maxDepth " + std::to_string(setup.rubric.maxDepth) + ")"
            : "the unbiased image";
    std::vector<std::string>& details = attempt.details;
    const RunFailure& failure = attempt.failure;
    if (!reproducibility.reproducible) {
        details.insert(details.begin(), reproducibility.details.begin(),
                       reproducibility.details.end());
        check.summary = (attempt.passed ? "mean radiance matches " + expected +
                                              ", but the same seed gives different images"
                                        : "mean radiance differs from " + expected +
                                              " (twice, on fresh seeds), and the same seed gives "
                                              "different images");
        check.diagnosis = NotReproducibleDiagnosis;
    } else if (check.passed) {
        check.summary = "mean radiance matches " + expected + parameterCheckText(setup, lab);
    } else if (!failure.empty()) {
        outcome.rendersFinished = false;
        check.summary = "could not be checked: " + failure.text;
        check.diagnosis = failure.kind;
        if (failure.kind == NonfiniteRadianceFailure)
            details.push_back("likely cause: " + likelyNonfiniteCause(lab));
    } else if (attempt.diagnosis == causeName(TooNoisyCause)) {
        check.summary = "could not be compared with " + expected +
                        ": your images are too noisy to judge (twice, on fresh seeds)";
        check.diagnosis = attempt.diagnosis;
    } else if (attempt.diagnosis == NotTracedDiagnosis) {
        check.summary = "mean radiance matches " + expected + " on the scenes you can see, but " +
                        NotTracedDiagnosis + " (twice, on fresh seeds)";
        check.diagnosis = attempt.diagnosis;
    } else {
        check.summary = "mean radiance differs from " + expected + " (twice, on fresh seeds)";
        check.diagnosis = attempt.diagnosis.empty() ? "wrong mean radiance" : attempt.diagnosis;
    }
    details.insert(details.end(), attempt.notes.begin(), attempt.notes.end());
    check.details = std::move(details);
    check.hiddenSceneDetails = std::move(attempt.hiddenDetails);
    return outcome;
}

GradingScene parameterCheckScene(const Rubric& rubric) {
    const ParameterCheck& check = rubric.parameterCheck;
    const auto model = furnaceModel(check.scene, check.maxDepth, check.continueProb);
    if (!model)
        throw InputError("rubric: parameter_check.scene '" + check.scene +
                         "' is not a furnace "
                         "of models/ (furnace, furnace_a08, mirror_furnace)");
    return analyticFurnaceScene(
        rubric, std::string(PATHLAB_MODELS_DIR) + "/" + check.scene + ".ecs", *model,
        check.scene + " at maxDepth " + std::to_string(check.maxDepth) + ", continueProb " +
            significant(check.continueProb, 2));
}

GradingScene analyticFurnaceScene(const Rubric& rubric, const std::string& path,
                                  const FurnaceModel& model, const std::string& name) {
    GradingScene scene;
    scene.path = path;
    const float continueProb = static_cast<float>(model.continueProb);
    scene.parameters = LabParameters{model.maxDepth, continueProb};
    scene.furnace = model;
    SceneReference& ref = scene.reference;
    ref = referenceHeader(name, rubric, model.maxDepth, continueProb);
    scene.name = ref.scene;
    // Every region of a furnace averages to its analytic value, known exactly: no standard error.
    auto analytic = [&](Lab lab) {
        return analyticExpectation(rubric, correctFurnaceValue(lab, *scene.furnace),
                                   furnaceFormula(lab, *scene.furnace));
    };
    ref.depthLimited = analytic(Lab::Branching);
    ref.unbiased = analytic(Lab::Roulette);
    return scene;
}

std::string failureAsShown(const std::string& failure, const std::string& kind,
                           const GradingScene& scene) {
    if (!scene.hidden) return failure;
    // The kinds render_run.cpp names, each in words of the grader's only.
    static const std::vector<std::pair<std::string, std::string>> words = {
        {"crashed", "crashed"},
        {"endless loop", "finished no sample for a long time (an endless loop?)"},
        {"too slow", "was too slow for the CPU time limit"},
        {"wall-clock limit", "did not finish within the wall-clock limit"},
        {"stopped itself", "stopped its own process"},
        {"out of memory", "ran out of memory"},
        {"exited with an error", "exited with an error"},
        {NonfiniteRadianceFailure, "returned NaN or infinite radiance"},
        {"unreadable output", "left output the grader could not read"},
    };
    const auto known = std::find_if(words.begin(), words.end(),
                                    [&](const auto& word) { return word.first == kind; });
    return (known != words.end() ? known->second : "failed") +
           " (on a hidden scene, what the lab printed is not shown)";
}

} // namespace pathlab::grader
