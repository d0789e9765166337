#include "grading.h"

#include "diagnosis.h"
#include "hypothesis_tests.h"
#include "seed_variance.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fcntl.h>
#include <sstream>
#include <sys/file.h>
#include <unistd.h>

namespace pathlab::grader {

double LabGrade::score() const {
    double s = 0;
    for (const CheckResult& c : checks) s += c.gradedHere ? c.score : 0;
    return s;
}

double LabGrade::maxScore() const {
    double s = 0;
    for (const CheckResult& c : checks) s += c.gradedHere ? c.maxScore : 0;
    return s;
}

double LabGrade::pointsNotGradedHere() const {
    double s = 0;
    for (const CheckResult& c : checks) s += c.gradedHere ? 0 : c.maxScore;
    return s;
}

namespace {

std::string format(const char* pattern, double a, double b = 0, double c = 0, double d = 0) {
    char text[256];
    std::snprintf(text, sizeof text, pattern, a, b, c, d);
    return text;
}

ProcessLimits limitsOf(const GraderSetup& s) {
    return {s.runSeconds > 0 ? s.runSeconds : s.rubric.secondsPerRun, s.rubric.memoryBytes};
}

/// k independent renders of one lab on one scene.
struct SceneRuns {
    std::vector<std::vector<double>> regionValues; ///< [statistic][seed]
    std::vector<std::vector<float>> images;        ///< one per seed
    std::string failure, failureKind;              ///< see RenderResult

    /// The mean of the seeds' images, for the reports' pictures.
    std::vector<float> meanImage() const {
        std::vector<float> mean(images.front().size(), 0.0f);
        for (const auto& image : images)
            for (size_t i = 0; i < image.size(); ++i) mean[i] += image[i] / static_cast<float>(images.size());
        return mean;
    }
};

SceneRuns renderSeeds(const GraderSetup& setup, const GradingScene& scene, Lab lab, uint64_t seedBase) {
    const Rubric& r = setup.rubric;
    SceneRuns runs;
    // All seeds in one viewer process: its start-up, longer than a small render, is paid once.
    const RenderRequest request{&setup.student, scene.path, lab, r.width, r.height,
                                r.correctnessSpp[static_cast<int>(lab)], r.maxDepth,
                                r.continueProb, seedBase, r.seeds, setup.threads, setup.scratch};
    const RenderResult result = renderLab(request, limitsOf(setup));
    if (!result.ok) {
        runs.failure = result.failure;
        runs.failureKind = result.failureKind;
        return runs;
    }
    for (const RenderedImage& rendered : result.images) {
        const std::vector<double> means = regionMeans(rendered.rgb, result.width, result.height, r.tiles);
        if (runs.regionValues.empty()) runs.regionValues.resize(means.size());
        for (size_t i = 0; i < means.size(); ++i) runs.regionValues[i].push_back(means[i]);
        runs.images.push_back(rendered.rgb);
    }
    return runs;
}

struct Comparison {
    std::vector<double> t, p;
    std::vector<MeanEstimate> observed;
};

/// Relative size of the float rounding between two renders of the same expectation at different
/// spp; see compare().
constexpr double floatRoundingFloor = 1e-5;

Comparison compare(const SceneRuns& runs, const Expectation& expected, int seeds) {
    Comparison c;
    for (size_t i = 0; i < runs.regionValues.size(); ++i) {
        const MeanEstimate m = batchMean(runs.regionValues[i]);
        // A region that every path sees alike (the blue of the refraction check, 0.2 through
        // the glass wherever it leads) has no sampling noise at all; there the means still
        // differ by float rounding, which grows with spp. That rounding, a few parts in 1e7
        // of a float accumulation, is bounded by a relative floor far below any bug's effect.
        const double rounding = floatRoundingFloor * std::fabs(expected.mean[i]);
        const double se = std::sqrt(m.standardError * m.standardError +
                                    expected.standardError[i] * expected.standardError[i] +
                                    rounding * rounding);
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

/// One attempt of the correctness check over all scenes; fills `details` and `diagnosis` on
/// rejection.
bool correctnessAttempt(const GraderSetup& setup, Lab lab, uint64_t seedBase, LabGrade& grade,
                        std::vector<std::string>& details, std::string& diagnosis,
                        RunFailure& failure, double& noise) {
    const Rubric& r = setup.rubric;
    std::vector<Comparison> comparisons;
    std::vector<double> allP;
    grade.pictures.clear();
    for (const GradingScene& scene : setup.scenes) {
        const SceneRuns runs = renderSeeds(setup, scene, lab, seedBase);
        if (!runs.failure.empty()) {
            failure = {"on " + scene.reference.scene + " the lab " + runs.failure, runs.failureKind};
            return false;
        }
        if (scene.reference.scene == r.noiseScene || noise < 0)
            noise = trimmedSampleVariance(runs.images, r.correctnessSpp[static_cast<int>(lab)]);
        comparisons.push_back(compare(runs, scene.reference.forLab(lab), r.seeds));
        allP.insert(allP.end(), comparisons.back().p.begin(), comparisons.back().p.end());
        LabGrade::Pictures pictures{scene.reference.scene, r.width, r.height, {}, scene.reference.forLab(lab).image};
        pictures.student = runs.meanImage();
        grade.pictures.push_back(std::move(pictures));
    }
    const std::vector<bool> rejected = holmRejections(allP, r.alpha);
    if (std::none_of(rejected.begin(), rejected.end(), [](bool b) { return b; })) return true;

    // Explain: per scene, the whole image's observed/expected per channel with a confidence
    // interval, the tiles that differ, and a likely cause where the furnace can tell.
    std::vector<bool> sceneRejected;
    for (size_t s = 0, offset = 0; s < setup.scenes.size(); offset += comparisons[s++].p.size())
        sceneRejected.push_back(std::any_of(rejected.begin() + offset,
                                            rejected.begin() + offset + comparisons[s].p.size(),
                                            [](bool b) { return b; }));
    // The furnaces have no glass: a lab that one of them rejects has a fault elsewhere, which the
    // refraction check's image shows too, so only a lab that every furnace accepts is told about
    // refraction.
    bool furnaceRejected = false;
    for (size_t s = 0; s < setup.scenes.size(); ++s)
        furnaceRejected = furnaceRejected || (setup.scenes[s].furnace && sceneRejected[s]);
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
        if (scene.furnace) furnaces.push_back({*scene.furnace, observed, c.observed[0].standardError});
        if (sceneRejected[s]) {
            std::string line = scene.reference.scene + ": observed/expected";
            for (int ch = 0; ch < 3; ++ch) {
                const double ratio = c.observed[ch].mean / e.mean[ch];
                const double half = critical * std::hypot(c.observed[ch].standardError, e.standardError[ch]) / e.mean[ch];
                line += std::string(" ") + channel[ch] + format(" %.3f [%.3f, %.3f]", ratio, ratio - half, ratio + half);
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
                tiles += " (" + std::to_string(tile % r.tiles) + "," + std::to_string(tile / r.tiles) + ")";
            }
            if (tileCount > 0)
                details.push_back(scene.reference.scene + ": " + std::to_string(tileCount) + " of " +
                                  std::to_string(r.tiles * r.tiles) + " tiles differ (column,row from the top left):" + tiles);
            if (scene.reference.scene == "refraction_check" && !furnaceRejected) {
                const std::string cause = likelyRefractionCause(lab);
                details.push_back("likely cause: " + cause);
                if (diagnosis.empty()) diagnosis = cause.substr(0, cause.find(':'));
            }
            if (scene.furnace)
                details.push_back(scene.reference.scene + format(": %.4f, where a correct lab gives %.4f",
                                                                 observed, correctFurnaceValue(lab, *scene.furnace)));
        }
        offset += c.p.size();
    }
    if (furnaceRejected) {
        const std::vector<std::string> causes = likelyFurnaceCauses(lab, furnaces);
        if (!causes.empty()) {
            details.push_back("likely cause: " + causes.front());
            // The furnaces' diagnosis is the most specific: it wins. Its name is the cause up to
            // the explanation after the colon.
            diagnosis = causes.front().substr(0, causes.front().find(':'));
        }
    }
    return false;
}

CheckResult checkCorrectness(const GraderSetup& setup, Lab lab, LabGrade& grade,
                             double& noise) {
    CheckResult check;
    check.name = "correctness";
    check.maxScore = setup.rubric.points[static_cast<int>(lab)].correctness;
    std::vector<std::string> details;
    std::string diagnosis;
    RunFailure failure;
    if (correctnessAttempt(setup, lab, setup.seedBase * 1000, grade, details, diagnosis, failure,
                           noise)) {
        check.passed = true;
    } else if (failure.empty()) {
        // A rejection at alpha happens to correct labs too, rarely: only a second rejection on
        // fresh seeds counts.
        std::vector<std::string> retryDetails;
        std::string retryDiagnosis;
        if (correctnessAttempt(setup, lab, setup.seedBase * 1000 + 500, grade, retryDetails,
                               retryDiagnosis, failure, noise))
            check.passed = true;
        else if (failure.empty())
            details = retryDetails, diagnosis = retryDiagnosis;
    }
    check.score = check.passed ? check.maxScore : 0;
    const std::string expected = isDepthLimited(lab)
                                     ? "the depth-limited image (maxDepth " + std::to_string(setup.rubric.maxDepth) + ")"
                                     : "the unbiased image";
    if (check.passed) {
        check.summary = "mean radiance matches " + expected;
    } else if (!failure.empty()) {
        grade.rendersFinished = false;
        check.summary = "could not be checked: " + failure.text;
        check.diagnosis = failure.kind;
        if (failure.kind == NonfiniteRadianceFailure)
            details.push_back("likely cause: " + likelyNonfiniteCause(lab));
    } else {
        check.summary = "mean radiance differs from " + expected + " (twice, on fresh seeds)";
        check.diagnosis = diagnosis.empty() ? "wrong mean radiance" : diagnosis;
    }
    check.details = details;
    return check;
}

/// The noise of the correctness runs on the noise scene against the reference solution's. Like
/// speed, it counts only for a correct lab: a lab that renders too little light is also quiet.
CheckResult checkNoise(const GraderSetup& setup, Lab lab, bool correct, double noise,
                       LabGrade& grade) {
    const Rubric& r = setup.rubric;
    CheckResult check;
    check.name = "noise";
    check.maxScore = r.points[static_cast<int>(lab)].noise;
    if (noise < 0) {
        check.summary = "could not be measured: the lab's renders failed (see correctness)";
        return check;
    }
    if (!correct) {
        // A wrong image's variance says nothing about the estimator: a lab missing light is
        // also quiet, one with NaN or an extra factor noisy. No ratio, then, to mislead.
        check.summary = "not compared: noise counts only for a correct lab";
        return check;
    }
    const auto scene = std::find_if(setup.scenes.begin(), setup.scenes.end(), [&](const GradingScene& s) {
        return s.reference.scene == r.noiseScene;
    });
    const GradingScene& noiseScene = scene != setup.scenes.end() ? *scene : setup.scenes.front();
    const double student = noise;
    const double solution = noiseScene.reference.noise[static_cast<int>(lab)];
    const double ratio = student / solution;
    grade.studentVariance = student;
    grade.solutionVariance = solution;
    check.summary = format("per-sample variance %.3g times the reference solution's (at most %.2g) on ", ratio, r.maxNoiseRatio) +
                    noiseScene.reference.scene;
    check.passed = ratio <= r.maxNoiseRatio;
    check.score = check.passed ? check.maxScore : 0;
    if (!check.passed) {
        check.diagnosis = "too noisy";
        check.details.push_back(format("variance per sample: yours %.4g, the reference's %.4g", student, solution));
        if (lab == Lab::Importance)
            check.details.push_back("an importance pick that picks uniformly, or that picks components "
                                    "whose reflectance is zero, is this noisy; the probabilities "
                                    "should follow reduceMax(Kd), reduceMax(Ks), reduceMax(Kt)");
        else if (lab == Lab::Roulette)
            check.details.push_back("Russian roulette should pick the component by importance, as in lab 3");
        else
            check.details.push_back("more noise than the reference at the same mean: is a component "
                                    "sampled with the wrong probability, or a random number reused?");
    }
    return check;
}

/// The mean of an image's pixels over all channels.
double imageMean(const std::vector<float>& image) {
    double sum = 0;
    for (float v : image) sum += v;
    return image.empty() ? 0 : sum / static_cast<double>(image.size());
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0 : v[v.size() / 2];
}

/// A runner for the timed runs: on the timing cores, when the policy names some.
LabRunner timedRunner(const LabRunner& runner, const TimingPolicy& timing) {
    LabRunner timed = runner;
    if (!timing.cpus.empty()) (timed.sandboxed() ? timed.sandbox.cpus : timed.cpus) = timing.cpus;
    return timed;
}

/// Holds an exclusive lock on a file while it lives (none for an empty path), so that the timed
/// series of concurrent gradings take turns.
class TimingLock {
public:
    explicit TimingLock(const std::string& path) {
        if (path.empty()) return;
        fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
        if (fd_ >= 0) ::flock(fd_, LOCK_EX);
    }
    ~TimingLock() {
        if (fd_ >= 0) ::close(fd_); // closing releases the lock
    }
    TimingLock(const TimingLock&) = delete;
    TimingLock& operator=(const TimingLock&) = delete;

private:
    int fd_ = -1;
};

/// The fixed cost of a run (start-up, loading, building Embree's BVH), measured by rendering one
/// pixel of `lab`, so that samples/s counts rendering alone and cannot be reported by the lab
/// itself.
double startupSeconds(const GraderSetup& setup, const LabRunner& runner, const std::string& scene,
                      Lab lab, int threads) {
    // Once per grading for each scene, lab, viewer (the sandboxed one starts slower) and thread
    // count: the speed check's own (Lab::Uniform) is measured just before its first timed runs,
    // apart from the time limits' (Lab::Branching), measured at the start of the grading.
    static std::map<std::string, double> measured;
    const std::string key = scene + "|" + std::string(labName(lab)) + "|" + runner.viewer + "|" +
                            runner.labsLibrary + "|" + std::to_string(threads);
    if (const auto known = measured.find(key); known != measured.end()) return known->second;
    std::vector<double> seconds;
    for (int i = 0; i < 3; ++i) {
        RenderRequest request{&runner, scene, lab, 1, 1, 1, setup.rubric.maxDepth,
                              setup.rubric.continueProb, 1, 1, threads, setup.scratch};
        const RenderResult r = renderLab(request, limitsOf(setup));
        if (r.ok) seconds.push_back(r.process.seconds);
    }
    return measured[key] = median(seconds);
}

/// The rubric's timed renders: where, how many threads, and the start-up to subtract (measured
/// with `startupRunner`'s `lab`).
struct TimedSeries {
    std::string scene;
    int threads = 0;
    double startup = 0;
};

TimedSeries timedSeries(const GraderSetup& setup, const LabRunner& startupRunner, Lab lab) {
    const Rubric& r = setup.rubric;
    const auto scene = std::find_if(setup.scenes.begin(), setup.scenes.end(), [&](const GradingScene& s) {
        return s.reference.scene == r.speedScene;
    });
    TimedSeries series;
    series.scene = scene != setup.scenes.end() ? scene->path
                                               : std::string(PATHLAB_MODELS_DIR) + "/" + r.speedScene + ".ecs";
    series.threads = setup.timing.threads > 0 ? setup.timing.threads : setup.threads;
    series.startup = startupSeconds(setup, startupRunner, series.scene, lab, series.threads);
    return series;
}

/// One timed render (run number `run` of a series): samples/s from its wall time minus the
/// start-up, and its image's mean radiance.
struct TimedRun {
    RenderResult result;
    double samplesPerSecond = 0, meanRadiance = 0;
};

TimedRun timedRun(const GraderSetup& setup, const TimedSeries& series, const LabRunner& runner,
                  Lab lab, int run) {
    const Rubric& r = setup.rubric;
    RenderRequest request{&runner, series.scene, lab, r.speedWidth, r.speedHeight,
                          r.speedSpp[static_cast<int>(lab)], r.maxDepth, r.continueProb,
                          static_cast<uint64_t>(77 + run), 1, series.threads, setup.scratch};
    TimedRun timed{renderLab(request, limitsOf(setup))};
    if (!timed.result.ok) return timed;
    const double samples = static_cast<double>(request.width) * request.height * request.spp;
    timed.samplesPerSecond = samples / std::max(timed.result.process.seconds - series.startup, 1e-3);
    timed.meanRadiance = imageMean(timed.result.image());
    return timed;
}

/// Speed in a build without the reference solutions: the student's timed runs alone, for the
/// ratios between labs; the check itself is the instructor's grader's.
CheckResult timeWithoutSolutions(const GraderSetup& setup, Lab lab, bool correct, LabGrade& grade) {
    const Rubric& r = setup.rubric;
    CheckResult check;
    check.name = "speed";
    check.maxScore = r.points[static_cast<int>(lab)].speed;
    // The instructor's grader gives a wrong lab no speed points: that much is known here.
    check.gradedHere = !correct;
    const LabRunner runner = timedRunner(setup.student, setup.timing);
    const TimedSeries series = timedSeries(setup, runner, lab);
    std::vector<double> samplesPerSecond;
    for (int run = 0; run < r.speedRuns; ++run) {
        const TimedRun timed = timedRun(setup, series, runner, lab, run);
        if (!timed.result.ok) break;
        samplesPerSecond.push_back(timed.samplesPerSecond);
    }
    grade.studentSamplesPerSecond = samplesPerSecond.size() == static_cast<size_t>(r.speedRuns)
                                        ? median(samplesPerSecond) : 0;
    grade.solutionSamplesPerSecond = setup.storedSolutionSamplesPerSecond[static_cast<int>(lab)];
    check.summary = correct ? format("graded by the instructor: this build has no reference "
                                     "solutions to time your lab against (at least %.2f of the "
                                     "reference's samples/s on the same machine)", r.minSpeedRatio)
                            : "speed counts only for a correct lab";
    if (grade.studentSamplesPerSecond > 0)
        check.details.push_back(format("yours on this machine: %.3g samples/s in the grader's "
                                       "timed runs (grading every lab prints the ratios between "
                                       "them)", grade.studentSamplesPerSecond));
    return check;
}

CheckResult checkSpeed(const GraderSetup& setup, Lab lab, bool correct, LabGrade& grade) {
    if (!setup.measureSpeed) return timeWithoutSolutions(setup, lab, correct, grade);
    const Rubric& r = setup.rubric;
    CheckResult check;
    check.name = "speed";
    check.maxScore = r.points[static_cast<int>(lab)].speed;
    const LabRunner studentRunner = timedRunner(setup.student, setup.timing);
    const LabRunner solutionRunner = timedRunner(setup.solution, setup.timing);
    const TimingLock lock(setup.timing.lockFile);
    const TimedSeries series = timedSeries(setup, solutionRunner, Lab::Uniform);
    std::vector<double> student, solution;
    std::vector<double> studentMeans, solutionMeans; // whole-image radiance of each timed run
    for (int run = 0; run < r.speedRuns; ++run) {
        // Interleaved A B A B: a slow spell of a shared machine hits both alike.
        for (const LabRunner* runner : {&studentRunner, &solutionRunner}) {
            const bool isStudent = runner == &studentRunner;
            const TimedRun timed = timedRun(setup, series, *runner, lab, run);
            if (!timed.result.ok) {
                check.summary = std::string(isStudent ? "the lab " : "the reference ") +
                                timed.result.failure + " in a timed run";
                check.diagnosis = isStudent ? timed.result.failureKind : "the reference failed";
                return check;
            }
            (isStudent ? student : solution).push_back(timed.samplesPerSecond);
            (isStudent ? studentMeans : solutionMeans).push_back(timed.meanRadiance);
        }
    }
    grade.studentSamplesPerSecond = median(student);
    grade.solutionSamplesPerSecond = median(solution);
    const double ratio = grade.studentSamplesPerSecond / grade.solutionSamplesPerSecond;
    check.summary = format("%.3g samples/s, %.2f times the reference solution's %.3g (at least %.2f)",
                           grade.studentSamplesPerSecond, ratio, grade.solutionSamplesPerSecond,
                           r.minSpeedRatio);
    if (!correct) {
        check.summary += "; speed counts only for a correct lab";
        return check;
    }
    // The timed runs must render the same image as the reference's too: a lab that is correct
    // in the correctness runs but cuts corners when it runs longer earns no speed points.
    const double floor = floatRoundingFloor * median(solutionMeans);
    if (r.speedRuns >= 2 && welchTwoSidedP(studentMeans, solutionMeans, floor) < r.alpha) {
        check.summary += "; the timed runs' mean radiance differs from the reference's, and "
                         "speed counts only for a correct timed run";
        check.diagnosis = "wrong image in the timed runs";
        check.details.push_back(format("mean radiance of the timed runs: yours %.4g, the "
                                       "reference's %.4g", median(studentMeans),
                                       median(solutionMeans)));
        return check;
    }
    check.passed = ratio >= r.minSpeedRatio;
    check.score = check.passed ? check.maxScore : 0;
    if (!check.passed) check.diagnosis = "too slow";
    if (!check.passed)
        check.details.push_back("slower than the reference at the same image: extra rays (e.g. a "
                                "shadow ray or bounce that is not needed), or work repeated per sample");
    return check;
}

} // namespace

double speedSceneStartUpSeconds(const GraderSetup& setup, const LabRunner& runner) {
    return timedSeries(setup, runner, Lab::Branching).startup;
}

LabGrade ungradedLab(const Rubric& rubric, Lab lab, bool measureSpeed, const std::string& reason,
                     const std::vector<std::string>& details) {
    LabGrade grade;
    grade.lab = lab;
    const LabPoints& points = rubric.points[static_cast<int>(lab)];
    std::vector<std::pair<std::string, double>> checks = {{"correctness", points.correctness},
                                                          {"noise", points.noise}};
    if (measureSpeed) checks.push_back({"speed", points.speed});
    for (const auto& [name, maxScore] : checks) {
        CheckResult check;
        check.name = name;
        check.maxScore = maxScore;
        check.summary = reason;
        check.diagnosis = reason;
        if (name == "correctness") check.details = details;
        grade.checks.push_back(check);
    }
    return grade;
}

double timedSamplesPerSecond(const GraderSetup& setup, const LabRunner& runner, Lab lab) {
    const LabRunner timed = timedRunner(runner, setup.timing);
    const TimedSeries series = timedSeries(setup, timed, lab);
    std::vector<double> samplesPerSecond;
    for (int run = 0; run < setup.rubric.speedRuns; ++run) {
        const TimedRun one = timedRun(setup, series, timed, lab, run);
        if (!one.result.ok) return 0;
        samplesPerSecond.push_back(one.samplesPerSecond);
    }
    return median(samplesPerSecond);
}

LabGrade gradeLab(const GraderSetup& setup, Lab lab) {
    LabGrade grade;
    grade.lab = lab;
    double noise = -1; // the noise figure of the correctness renders on the noise scene
    grade.checks.push_back(checkCorrectness(setup, lab, grade, noise));
    grade.checks.push_back(checkNoise(setup, lab, grade.checks[0].passed, noise, grade));
    if (!setup.measureSpeed && !setup.timeWithoutSolutions) return grade;
    if (grade.rendersFinished) {
        grade.checks.push_back(checkSpeed(setup, lab, grade.checks[0].passed, grade));
    } else {
        // A lab that crashed or hung in 64x64 renders would do the same in longer ones.
        CheckResult speed;
        speed.name = "speed";
        speed.maxScore = setup.rubric.points[static_cast<int>(lab)].speed;
        speed.summary = "not measured: the lab's correctness renders failed, and speed counts "
                        "only for a correct lab";
        grade.checks.push_back(speed);
    }
    return grade;
}

} // namespace pathlab::grader
