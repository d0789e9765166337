#include "checks/correctness_check.h"

#include "checks/hypothesis_tests.h"
#include "checks/number_text.h"
#include "checks/path_length.h"
#include "checks/rays_per_sample.h"
#include "checks/reproducibility_check.h"
#include "checks/run_limits.h"
#include "checks/seed_variance.h"
#include "diagnosis/diagnosis.h"

#include "pathlab/input_error.h"
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
    // All seeds in one viewer process: its start-up, longer than a small render, is paid once.
    const LabParameters parameters =
        scene.parameters.value_or(LabParameters{r.maxDepth, r.continueProb});
    const int spp = r.forLab(lab).correctnessSpp;
    const RenderRequest request{&setup.student,
                                scene.path,
                                lab,
                                r.width,
                                r.height,
                                spp,
                                parameters.maxDepth,
                                parameters.continueProb,
                                seedBase,
                                r.seeds,
                                setup.threads,
                                setup.scratch};
    const RenderResult result = renderLab(request, limitsOf(setup));
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

struct Comparison {
    std::vector<double> t, p;
    std::vector<MeanEstimate> observed;
};

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

/// Why a lab's renders could not be compared at all.
struct RunFailure {
    std::string text, kind;
    bool empty() const { return text.empty(); }
};

/// What one attempt over all scenes found: on rejection, the details and diagnosis.
struct Attempt {
    bool passed = false;
    std::vector<std::string> details, hiddenDetails;
    std::string diagnosis;
    RunFailure failure;
    double noise = -1; ///< see CorrectnessOutcome
    std::vector<LabGrade::Pictures> pictures;
    /// The first seed's image of the noise scene (or of the first scene), rendered again by the
    /// reproducibility check.
    SeedImage firstImage;
};

/// One attempt of the correctness check over all scenes. `noise`: the figure of an earlier
/// attempt (-1: none), kept where this one does not reach the noise scene.
Attempt correctnessAttempt(const GraderSetup& setup, Lab lab, uint64_t seedBase, double noise) {
    const Rubric& r = setup.rubric;
    Attempt attempt;
    attempt.noise = noise;
    std::vector<std::string>& details = attempt.details;
    std::vector<std::string>& hiddenDetails = attempt.hiddenDetails;
    std::string& diagnosis = attempt.diagnosis;
    std::vector<Comparison> comparisons;
    std::vector<double> allP;
    std::vector<PathLengthObservation> pathLengths; // lab 4 in the diffuse furnaces
    bool stepsOpen = false;
    for (const GradingScene& scene : setup.scenes) {
        const SceneRuns runs = renderSeeds(setup, scene, lab, seedBase);
        if (!runs.failure.empty()) {
            attempt.failure = {"on " + scene.name + " the lab " +
                                   withoutSceneName(runs.failure, scene),
                               runs.failureKind};
            return attempt;
        }
        stepsOpen = stepsOpen || runs.stepsOpen;
        if (scene.reference.scene == r.noiseScene || attempt.noise < 0)
            attempt.noise = trimmedSampleVariance(runs.images, r.forLab(lab).correctnessSpp);
        if (scene.reference.scene == r.noiseScene || !attempt.firstImage.scene)
            attempt.firstImage = {&scene, seedBase, setup.threads, runs.images.front()};
        if (lab == Lab::Roulette && scene.furnace && scene.furnace->walls == FurnaceWalls::Diffuse)
            pathLengths.push_back({scene.furnace->continueProb, runs.rays.bounce});
        comparisons.push_back(compare(runs, scene.reference.forLab(lab), r.seeds));
        allP.insert(allP.end(), comparisons.back().p.begin(), comparisons.back().p.end());
        if (scene.hidden) continue; // its images are the instructor's
        LabGrade::Pictures pictures{
            scene.name, r.width, r.height, {}, scene.reference.forLab(lab).image};
        pictures.student = runs.meanImage();
        attempt.pictures.push_back(std::move(pictures));
    }
    const std::vector<bool> rejected = holmRejections(allP, r.alpha);
    // A lab 4 that continues with a constant of its own is unbiased, but not lab 4: its paths
    // tell (path_length.h). That cause wins over any the images suggest.
    const std::string ignored = ignoredContinueProb(pathLengths);
    if (!ignored.empty()) {
        details.push_back("likely cause: " + ignored);
        diagnosis = ignored.substr(0, ignored.find(':'));
        return attempt;
    }
    if (std::none_of(rejected.begin(), rejected.end(), [](bool b) { return b; })) {
        if (const std::string note = pathLengthNote(pathLengths); !note.empty())
            details.push_back(note);
        for (const GradingScene& scene : setup.scenes)
            if (scene.hidden) hiddenDetails.push_back(scene.name + HiddenSceneMatches);
        attempt.passed = true;
        return attempt;
    }

    // Explain: per scene, the whole image's observed/expected per channel with a confidence
    // interval, the tiles that differ, and a likely cause where the furnace can tell.
    std::vector<bool> sceneRejected;
    for (size_t s = 0, offset = 0; s < setup.scenes.size(); offset += comparisons[s++].p.size())
        sceneRejected.push_back(std::any_of(rejected.begin() + offset,
                                            rejected.begin() + offset + comparisons[s].p.size(),
                                            [](bool b) { return b; }));
    // The furnaces have no glass: a lab that one of them rejects has a fault elsewhere, which the
    // refraction check's image shows too, so only a lab that every furnace accepts is told about
    // refraction; and only one that the refraction check accepts too about its diffuse
    // directions (mixed_surfaces holds glass as well).
    bool furnaceRejected = false, refractionRejected = false;
    for (size_t s = 0; s < setup.scenes.size(); ++s) {
        furnaceRejected = furnaceRejected || (setup.scenes[s].furnace && sceneRejected[s]);
        refractionRejected =
            refractionRejected ||
            (!setup.scenes[s].hidden && setup.scenes[s].reference.scene == "refraction_check" &&
             sceneRejected[s]);
    }
    // Every furnace's value, accepted or not, narrows down the known bugs that explain them.
    std::vector<FurnaceObservation> furnaces;
    size_t offset = 0;
    const double critical = studentCritical(r.alpha, r.seeds - 1);
    const char* channel[3] = {"red", "green", "blue"};
    for (size_t s = 0; s < setup.scenes.size(); ++s) {
        const GradingScene& scene = setup.scenes[s];
        const Comparison& c = comparisons[s];
        const Expectation& e = scene.reference.forLab(lab);
        const double observed = (c.observed[0].mean + c.observed[1].mean + c.observed[2].mean) / 3;
        if (scene.furnace)
            furnaces.push_back({*scene.furnace, observed, c.observed[0].standardError});
        if (scene.hidden) {
            hiddenDetails.push_back(scene.name +
                                    (sceneRejected[s] ? HiddenSceneDiffers : HiddenSceneMatches));
        } else if (sceneRejected[s]) {
            std::string line = scene.name + ": observed/expected";
            std::vector<ChannelInterval> intervals;
            for (int ch = 0; ch < 3; ++ch) {
                const double ratio = c.observed[ch].mean / e.mean[ch];
                const double half = critical *
                                    std::hypot(c.observed[ch].standardError, e.standardError[ch]) /
                                    e.mean[ch];
                line += std::string(" ") + channel[ch] + " " + fixed(ratio, 3) + " [" +
                        fixed(ratio - half, 3) + ", " + fixed(ratio + half, 3) + "]";
                intervals.push_back({ratio - half, ratio + half});
            }
            details.push_back(line);
            std::string tiles;
            int tileCount = 0;
            for (size_t i = 3; i < c.p.size(); i += 3) {
                bool any = false;
                for (int ch = 0; ch < 3; ++ch) any = any || rejected[offset + i + ch];
                if (!any) continue;
                const int tile = static_cast<int>(i / 3) - 1;
                ++tileCount;
                tiles += " (" + std::to_string(tile % r.tiles) + "," +
                         std::to_string(tile / r.tiles) + ")";
            }
            if (tileCount > 0)
                details.push_back(scene.name + ": " + std::to_string(tileCount) + " of " +
                                  std::to_string(r.tiles * r.tiles) +
                                  " tiles differ (column,row from the top left):" + tiles);
            if (scene.reference.scene == "mixed_surfaces" && !furnaceRejected &&
                !refractionRejected) {
                // Channels off in opposite ways point to the pick's probabilities, channels off
                // alike to the diffuse directions (channelsOffOppositeWays). Lab 1 picks nothing:
                // it is told only what differs.
                const bool opposite = channelsOffOppositeWays(intervals);
                const std::string cause =
                    opposite ? likelyPickDivideCause(lab) : likelyDirectionCause(lab);
                if (!cause.empty()) {
                    details.push_back("likely cause: " + cause);
                    if (diagnosis.empty()) diagnosis = cause.substr(0, cause.find(':'));
                } else if (opposite) {
                    details.push_back(scene.name +
                                      ": some colour channels are too bright and others too dark");
                }
            }
            if (scene.reference.scene == "refraction_check" && !furnaceRejected) {
                const std::string cause = likelyRefractionCause(lab);
                details.push_back("likely cause: " + cause);
                if (diagnosis.empty()) diagnosis = cause.substr(0, cause.find(':'));
            }
            if (scene.furnace)
                details.push_back(scene.name + ": " + fixed(observed, 4) +
                                  ", where a correct lab gives " +
                                  fixed(correctFurnaceValue(lab, *scene.furnace), 4));
        }
        offset += c.p.size();
    }
    bool publicRejected = false;
    for (size_t s = 0; s < setup.scenes.size(); ++s)
        publicRejected = publicRejected || (!setup.scenes[s].hidden && sceneRejected[s]);
    if (!publicRejected)
        hiddenDetails.push_back("every scene you can see matches: what differs is something only a "
                                "hidden scene has (a material, a light or a path the public scenes "
                                "lack)");
    if (furnaceRejected) {
        const std::vector<std::string> causes = likelyFurnaceCauses(lab, furnaces, stepsOpen);
        if (!causes.empty()) {
            details.push_back("likely cause: " + causes.front());
            // The furnaces' diagnosis is the most specific: it wins. Its name is the cause up to
            // the explanation after the colon.
            diagnosis = causes.front().substr(0, causes.front().find(':'));
        }
    }
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
    Attempt attempt = correctnessAttempt(setup, lab, setup.seedBase * 1000, -1);
    if (!attempt.passed && attempt.failure.empty()) {
        // A rejection at alpha happens to correct labs too, rarely: only a second rejection on
        // fresh seeds counts. A retry whose renders fail keeps the first attempt's words.
        Attempt retry = correctnessAttempt(setup, lab, setup.seedBase * 1000 + 500, attempt.noise);
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
    } else {
        check.summary = "mean radiance differs from " + expected + " (twice, on fresh seeds)";
        check.diagnosis = attempt.diagnosis.empty() ? "wrong mean radiance" : attempt.diagnosis;
    }
    check.details = std::move(details);
    check.hiddenSceneDetails = std::move(attempt.hiddenDetails);
    return outcome;
}

GradingScene parameterCheckScene(const Rubric& rubric) {
    const ParameterCheck& check = rubric.parameterCheck;
    GradingScene scene;
    scene.path = std::string(PATHLAB_MODELS_DIR) + "/" + check.scene + ".ecs";
    scene.parameters = LabParameters{check.maxDepth, check.continueProb};
    scene.furnace = furnaceModel(check.scene, check.maxDepth, check.continueProb);
    if (!scene.furnace)
        throw InputError("rubric: parameter_check.scene '" + check.scene +
                         "' is not a furnace "
                         "of models/ (furnace, furnace_a08, mirror_furnace)");
    SceneReference& ref = scene.reference;
    ref = referenceHeader(check.scene + " at maxDepth " + std::to_string(check.maxDepth) +
                              ", continueProb " + significant(check.continueProb, 2),
                          rubric, check.maxDepth, check.continueProb);
    scene.name = ref.scene;
    // Every region of a furnace averages to its analytic value, known exactly: no standard error.
    const size_t values = 3 * (1 + static_cast<size_t>(rubric.tiles) * rubric.tiles);
    const size_t pixels = 3 * static_cast<size_t>(rubric.width) * rubric.height;
    auto analytic = [&](Lab lab) {
        const double value = correctFurnaceValue(lab, *scene.furnace);
        Expectation e;
        e.solution = "analytic: " + furnaceFormula(lab, *scene.furnace);
        e.mean.assign(values, value);
        e.standardError.assign(values, 0.0);
        e.image.assign(pixels, static_cast<float>(value));
        return e;
    };
    ref.depthLimited = analytic(Lab::Branching);
    ref.unbiased = analytic(Lab::Roulette);
    return scene;
}

std::string withoutSceneName(std::string text, const GradingScene& scene) {
    if (!scene.hidden) return text;
    for (const std::string& secret : {scene.path, scene.reference.scene}) {
        if (secret.empty()) continue;
        for (size_t at = text.find(secret); at != std::string::npos;
             at = text.find(secret, at + scene.name.size()))
            text.replace(at, secret.size(), scene.name);
    }
    return text;
}

} // namespace pathlab::grader
