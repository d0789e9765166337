#include "checks/speed_check.h"

#include "checks/hypothesis_tests.h"
#include "checks/number_text.h"
#include "checks/rays_per_sample.h"
#include "checks/run_limits.h"
#include "isolation/timing_lock.h"

#include <algorithm>
#include <optional>

namespace pathlab::grader {

namespace {

/// The mean of an image's pixels over all channels.
double imageMean(const std::vector<float>& image) {
    double sum = 0;
    for (float v : image) sum += v;
    return image.empty() ? 0 : sum / static_cast<double>(image.size());
}

/// A runner for the timed runs: on the timing cores, when the policy names some.
LabRunner timedRunner(const LabRunner& runner, const TimingPolicy& timing) {
    LabRunner timed = runner;
    if (!timing.cpus.empty()) (timed.sandboxed() ? timed.sandbox.cpus : timed.cpus) = timing.cpus;
    return timed;
}

/// The fixed cost of a run (start-up, loading, building Embree's BVH), measured by rendering one
/// pixel of `lab`, so that samples/s counts rendering alone and cannot be reported by the lab
/// itself.
double startupSeconds(const GraderSetup& setup, const LabRunner& runner, const std::string& scene,
                      Lab lab, int threads, StartUpTimes& startUps) {
    // Once per grading for each scene, lab, viewer (the sandboxed one starts slower) and thread
    // count: the speed check's own (Lab::Uniform) is measured just before its first timed runs,
    // apart from the time limits' (Lab::Branching), measured at the start of the grading.
    const std::string what = scene + "|" + std::string(labName(lab)) + "|" + runner.viewer + "|" +
                             runner.libraryFor(lab) + "|" + std::to_string(threads);
    return startUps.seconds(what, [&] {
        std::vector<double> seconds;
        for (int i = 0; i < 3; ++i) {
            RenderRequest request{&runner,
                                  scene,
                                  lab,
                                  1,
                                  1,
                                  1,
                                  setup.rubric.maxDepth,
                                  setup.rubric.continueProb,
                                  1,
                                  1,
                                  threads,
                                  setup.scratch};
            const RenderResult r = renderLab(request, limitsOf(setup));
            if (r.ok) seconds.push_back(r.process.seconds);
        }
        return median(seconds);
    });
}

/// The rubric's timed renders: where, how many threads, and the start-up to subtract (measured
/// with `startupRunner`'s `lab`).
struct TimedSeries {
    std::string scene;
    int threads = 0;
    double startup = 0;
};

TimedSeries timedSeries(const GraderSetup& setup, const LabRunner& startupRunner, Lab lab,
                        StartUpTimes& startUps) {
    const Rubric& r = setup.rubric;
    const auto scene =
        std::find_if(setup.scenes.begin(), setup.scenes.end(),
                     [&](const GradingScene& s) { return s.reference.scene == r.speedScene; });
    TimedSeries series;
    series.scene = scene != setup.scenes.end()
                       ? scene->path
                       : std::string(PATHLAB_MODELS_DIR) + "/" + r.speedScene + ".ecs";
    series.threads = setup.timing.threads > 0 ? setup.timing.threads : setup.threads;
    series.startup =
        startupSeconds(setup, startupRunner, series.scene, lab, series.threads, startUps);
    return series;
}

/// One timed render (run number `run` of a series): samples/s from its wall time minus the
/// start-up, and its image's mean radiance.
struct TimedRun {
    RenderResult result;
    double samplesPerSecond = 0, meanRadiance = 0;
    double samples = 0; ///< width x height x spp
};

TimedRun timedRun(const GraderSetup& setup, const TimedSeries& series, const LabRunner& runner,
                  Lab lab, int run) {
    const Rubric& r = setup.rubric;
    RenderRequest request{&runner,
                          series.scene,
                          lab,
                          r.speedWidth,
                          r.speedHeight,
                          r.forLab(lab).speedSpp,
                          r.maxDepth,
                          r.continueProb,
                          static_cast<uint64_t>(77 + run),
                          1,
                          series.threads,
                          setup.scratch};
    TimedRun timed{renderLab(request, limitsOf(setup))};
    if (!timed.result.ok) return timed;
    timed.samples = static_cast<double>(request.width) * request.height * request.spp;
    timed.samplesPerSecond =
        timed.samples / std::max(timed.result.process.seconds - series.startup, 1e-3);
    timed.meanRadiance = imageMean(timed.result.image());
    return timed;
}

/// The rubric's timed runs of one lab with one runner, in a row (no reference beside them).
struct TimedRuns {
    std::vector<double> samplesPerSecond; ///< one per run that finished
    RayCounters rays;
    double samples = 0;
    bool complete = false; ///< every run finished

    double medianSamplesPerSecond() const { return complete ? median(samplesPerSecond) : 0; }
};

TimedRuns timedRuns(const GraderSetup& setup, const LabRunner& runner, Lab lab,
                    StartUpTimes& startUps) {
    const LabRunner timed = timedRunner(runner, setup.timing);
    const TimedSeries series = timedSeries(setup, timed, lab, startUps);
    TimedRuns runs;
    for (int run = 0; run < setup.rubric.speedRuns; ++run) {
        const TimedRun one = timedRun(setup, series, timed, lab, run);
        if (!one.result.ok) return runs;
        runs.samplesPerSecond.push_back(one.samplesPerSecond);
        runs.rays += one.result.images.front().rays;
        runs.samples += one.samples;
    }
    runs.complete = true;
    return runs;
}

/// Speed in a build without the reference solutions: the student's timed runs alone, for the
/// ratios between labs; the check itself is the instructor's grader's.
SpeedOutcome timeWithoutSolutions(const GraderSetup& setup, Lab lab, bool correct,
                                  StartUpTimes& startUps) {
    const Rubric& r = setup.rubric;
    SpeedOutcome outcome;
    CheckResult& check = outcome.check;
    check.kind = CheckKind::Speed;
    check.maxScore = r.forLab(lab).points.speed;
    // The instructor's grader gives a wrong lab no speed points: that much is known here.
    check.gradedHere = !correct;
    const TimedRuns runs = timedRuns(setup, setup.student, lab, startUps);
    outcome.studentRays = raysPerSample(runs.rays, runs.samples);
    outcome.studentSamplesPerSecond = runs.medianSamplesPerSecond();
    outcome.solutionSamplesPerSecond = setup.storedSolutionSamplesPerSecond[lab];
    check.summary = correct ? "graded by the instructor: this build has no reference solutions to "
                              "time your lab against (at least " +
                                  fixed(r.minSpeedRatio, 2) +
                                  " of the reference's samples/s on the same machine)"
                            : "speed counts only for a correct lab";
    if (outcome.studentSamplesPerSecond > 0)
        check.details.push_back(
            "yours on this machine: " + significant(outcome.studentSamplesPerSecond, 3) +
            " samples/s in the grader's timed runs (grading every lab prints "
            "the ratios between them); rays per sample: " +
            raysText(outcome.studentRays));
    return outcome;
}

/// One lab's timed series, interleaved with the reference's.
struct TimedComparison {
    std::vector<double> student, solution;           ///< samples/s of each run
    std::vector<double> studentMeans, solutionMeans; ///< whole-image radiance of each run
    RayCounters studentRays, solutionRays;
    double studentSamples = 0, solutionSamples = 0;
};

std::string measureName(SpeedMeasure measure) {
    return measure == SpeedMeasure::Efficiency ? "efficiency (time to equal noise)" : "samples/s";
}

/// Whether the timed figures pass, and why in words.
struct SpeedVerdict {
    bool passed = false;
    std::vector<std::string> details;
    std::string diagnosis;
};

/// The speed check's verdict and its words, from the measured figures: `perSample`, the
/// samples/s ratio, and `efficiencyRatio` (0: unknown), yours over the reference's.
SpeedVerdict judgeSpeed(const GraderSetup& setup, Lab lab, double perSample, double efficiencyRatio,
                        const RaysPerSample& studentRays, const RaysPerSample& solutionRays) {
    const Rubric& r = setup.rubric;
    const SpeedMeasure measure = r.forLab(lab).speedJudgedBy;
    const double ratio = measure == SpeedMeasure::Efficiency ? efficiencyRatio : perSample;
    SpeedVerdict verdict;
    verdict.passed = ratio >= r.minSpeedRatio;
    const std::string departure = specificationDeparture(lab, studentRays, solutionRays);
    const bool moreEfficient = efficiencyRatio >= 1;
    if (perSample < r.minSpeedRatio && moreEfficient) {
        // Slower per sample, yet less time to the same noise: a different estimator from the
        // handout's, better in this sense. Said as it is, whichever measure the rubric takes.
        verdict.details.push_back("slower than the reference per sample (" + fixed(perSample, 2) +
                                  " times its samples/s) but more efficient: it reaches the same "
                                  "noise in " +
                                  fixed(1 / efficiencyRatio, 2) + " of the reference's time");
        if (!departure.empty())
            verdict.details.push_back("it departs from the lab's specification: " + departure);
        verdict.details.push_back(
            measure == SpeedMeasure::Efficiency
                ? "the rubric judges this lab's speed by efficiency: time to "
                  "equal noise"
                : "the rubric judges this lab's speed by samples/s, the lab as "
                  "its handout specifies it: implement the lab's estimator "
                  "for these points");
        if (!verdict.passed) verdict.diagnosis = "slower per sample, more efficient";
        return verdict;
    }
    if (verdict.passed) {
        if (!departure.empty()) verdict.details.push_back("note: " + departure);
        return verdict;
    }
    verdict.diagnosis = "too slow";
    if (measure == SpeedMeasure::Efficiency && perSample >= r.minSpeedRatio) {
        // Judged by efficiency: fast enough per sample, but noisier.
        verdict.diagnosis = "less efficient";
        verdict.details.push_back(
            "fast enough per sample (" + fixed(perSample, 2) +
            " times the reference's samples/s) but less efficient: the same "
            "noise takes " +
            fixed(1 / efficiencyRatio, 2) +
            " times the reference's time, for its variance per sample is higher");
        if (!departure.empty())
            verdict.details.push_back("it departs from the lab's specification: " + departure);
        return verdict;
    }
    if (!departure.empty())
        verdict.details.push_back("slower than the reference at the same image: " + departure);
    else if (studentRays.bounce <= 1.15 * solutionRays.bounce + 0.02)
        verdict.details.push_back("slower than the reference at the same image, with no more rays "
                                  "per sample: the time goes into work repeated per sample (or "
                                  "work between samples, such as allocations)");
    else
        verdict.details.push_back("slower than the reference at the same image: extra rays (a "
                                  "shadow ray or bounce that is not needed), or work repeated per "
                                  "sample");
    return verdict;
}

/// The rubric's timed series of the lab and of the reference, interleaved A B A B so that a slow
/// spell of a shared machine hits both alike; on the timing cores, holding the machine's timing
/// lock. A run that fails ends it: nullopt, with the check's summary and diagnosis saying so.
std::optional<TimedComparison> timeInterleaved(const GraderSetup& setup, Lab lab,
                                               CheckResult& check, StartUpTimes& startUps) {
    const LabRunner studentRunner = timedRunner(setup.student, setup.timing);
    const LabRunner solutionRunner = timedRunner(setup.solution, setup.timing);
    const TimingLock lock(setup.timing.lockFile);
    const TimedSeries series = timedSeries(setup, solutionRunner, Lab::Uniform, startUps);
    TimedComparison t;
    for (int run = 0; run < setup.rubric.speedRuns; ++run) {
        for (const LabRunner* runner : {&studentRunner, &solutionRunner}) {
            const bool isStudent = runner == &studentRunner;
            const TimedRun timed = timedRun(setup, series, *runner, lab, run);
            if (!timed.result.ok) {
                check.summary = std::string(isStudent ? "the lab " : "the reference ") +
                                timed.result.failure + " in a timed run";
                check.diagnosis = isStudent ? timed.result.failureKind : "the reference failed";
                return std::nullopt;
            }
            (isStudent ? t.student : t.solution).push_back(timed.samplesPerSecond);
            (isStudent ? t.studentMeans : t.solutionMeans).push_back(timed.meanRadiance);
            (isStudent ? t.studentRays : t.solutionRays) += timed.result.images.front().rays;
            (isStudent ? t.studentSamples : t.solutionSamples) += timed.samples;
        }
    }
    return t;
}

/// Each pair's samples/s ratio, yours over the reference's: the two runs of a pair ran back to
/// back, under the same load, which the ratio of the two medians would not keep together.
std::vector<double> pairRatios(const TimedComparison& t) {
    std::vector<double> ratios;
    for (size_t i = 0; i < t.student.size(); ++i) ratios.push_back(t.student[i] / t.solution[i]);
    return ratios;
}

/// Efficiency needs both variances, which the noise check measures for a correct lab only.
bool variancesKnown(const SampleVariances& variances) {
    return variances.student > 0 && variances.solution > 0;
}

/// The figures every verdict is told with: the summary's samples/s, ratio and measure, and the
/// details' rays and variances per sample. `pairs`: how many interleaved pairs `ratio` is the
/// median of.
void describeTimedRuns(const Rubric& r, Lab lab, double ratio, size_t pairs,
                       const SampleVariances& variances, SpeedOutcome& outcome) {
    CheckResult& check = outcome.check;
    check.summary = significant(outcome.studentSamplesPerSecond, 3) + " samples/s, " +
                    fixed(ratio, 2) + " times the reference solution's " +
                    significant(outcome.solutionSamplesPerSecond, 3) + " (the median of " +
                    std::to_string(pairs) + " interleaved pairs)";
    if (variancesKnown(variances))
        check.summary +=
            "; efficiency " + fixed(outcome.efficiencyRatio, 2) + " times the reference's";
    check.summary += "; judged by " + measureName(r.forLab(lab).speedJudgedBy) + " (at least " +
                     fixed(r.minSpeedRatio, 2) + ")";
    check.details.push_back("rays per sample: yours " + raysText(outcome.studentRays) +
                            ", the reference's " + raysText(outcome.solutionRays));
    if (variancesKnown(variances))
        check.details.push_back("variance per sample: yours " + significant(variances.student, 4) +
                                ", the reference's " + significant(variances.solution, 4) +
                                "; efficiency = 1/(variance per sample x time per sample)");
}

/// The timed runs must render the same image as the reference's too: a lab that is correct in
/// the correctness runs but cuts corners when it runs longer earns no speed points. Says so in
/// `check` when they do not.
bool timedImageDiffers(const Rubric& r, const TimedComparison& t, CheckResult& check) {
    const double floor = floatRoundingFloor * median(t.solutionMeans);
    const bool differs =
        r.speedRuns >= 2 && welchTwoSidedP(t.studentMeans, t.solutionMeans, floor) < r.alpha;
    if (!differs) return false;
    check.summary += "; the timed runs' mean radiance differs from the reference's, and "
                     "speed counts only for a correct timed run";
    check.diagnosis = "wrong image in the timed runs";
    check.details.push_back("mean radiance of the timed runs: yours " +
                            significant(median(t.studentMeans), 4) + ", the reference's " +
                            significant(median(t.solutionMeans), 4));
    return true;
}

} // namespace

SpeedOutcome checkSpeed(const GraderSetup& setup, Lab lab, bool correct,
                        const SampleVariances& variances, StartUpTimes& startUps) {
    if (!setup.measureSpeed) return timeWithoutSolutions(setup, lab, correct, startUps);
    const Rubric& r = setup.rubric;
    SpeedOutcome outcome;
    CheckResult& check = outcome.check;
    check.kind = CheckKind::Speed;
    check.maxScore = r.forLab(lab).points.speed;
    const std::optional<TimedComparison> timed = timeInterleaved(setup, lab, check, startUps);
    if (!timed) return outcome;
    const TimedComparison& t = *timed;
    outcome.studentSamplesPerSecond = median(t.student);
    outcome.solutionSamplesPerSecond = median(t.solution);
    outcome.studentRays = raysPerSample(t.studentRays, t.studentSamples);
    outcome.solutionRays = raysPerSample(t.solutionRays, t.solutionSamples);
    const std::vector<double> pairs = pairRatios(t);
    const double ratio = median(pairs);
    // Efficiency, 1/(variance per sample x time per sample), from the noise check's variances
    // (the same scene) and these samples/s.
    outcome.efficiencyRatio =
        variancesKnown(variances) ? ratio * variances.solution / variances.student : 0;
    describeTimedRuns(r, lab, ratio, pairs.size(), variances, outcome);
    if (!correct) {
        check.summary += "; speed counts only for a correct lab";
        return outcome;
    }
    if (timedImageDiffers(r, t, check)) return outcome;
    if (r.forLab(lab).speedJudgedBy == SpeedMeasure::Efficiency && !variancesKnown(variances)) {
        // Cannot happen for a correct lab (the noise check measures both); said if it does.
        check.summary += "; efficiency unknown: the variances were not measured";
        check.diagnosis = "efficiency unknown";
        return outcome;
    }
    SpeedVerdict verdict = judgeSpeed(setup, lab, ratio, outcome.efficiencyRatio,
                                      outcome.studentRays, outcome.solutionRays);
    check.passed = verdict.passed;
    check.score = check.passed ? check.maxScore : 0;
    check.details.insert(check.details.end(), verdict.details.begin(), verdict.details.end());
    check.diagnosis = std::move(verdict.diagnosis);
    return outcome;
}

double speedSceneStartUpSeconds(const GraderSetup& setup, const LabRunner& runner,
                                StartUpTimes& startUps) {
    return timedSeries(setup, runner, Lab::Branching, startUps).startup;
}

double timedSamplesPerSecond(const GraderSetup& setup, const LabRunner& runner, Lab lab,
                             StartUpTimes& startUps) {
    return timedRuns(setup, runner, lab, startUps).medianSamplesPerSecond();
}

} // namespace pathlab::grader
