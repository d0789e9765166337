#include "checks/speed_check.h"

#include "checks/correctness_renders.h"
#include "checks/hypothesis_tests.h"
#include "checks/number_text.h"
#include "checks/rays_per_sample.h"
#include "checks/run_limits.h"
#include "isolation/timing_lock.h"

#include "pathlab/render/renderer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

namespace pathlab::grader {

namespace {

/// A runner for the timed runs: on the timing cores, when the policy names some.
LabRunner timedRunner(const LabRunner& runner, const TimingPolicy& timing) {
    LabRunner timed = runner;
    if (!timing.cpus.empty()) (timed.sandboxed() ? timed.sandbox.cpus : timed.cpus) = timing.cpus;
    return timed;
}

/// The CPU time of a run's start-up (loading the scene, building Embree's BVH), measured by
/// rendering one pixel with the reference solutions' labs, never the lab's own: so that
/// samples per CPU-second count rendering alone, and no lab can make its start-up look longer.
double startUpCpuSeconds(const GraderSetup& setup, const LabRunner& runner,
                         const GradingScene& scene, StartUpTimes& startUps) {
    // Once per grading for each viewer (the sandboxed one starts slower) and thread count.
    const std::string what = "cpu|" + scene.path + "|" + runner.viewer + "|" +
                             runner.libraryFor(Lab::Branching) + "|" +
                             std::to_string(setup.threads);
    return startUps.seconds(what, [&] {
        std::vector<double> seconds;
        for (int i = 0; i < 3; ++i) {
            RenderRequest request = correctnessRequest(setup, scene, Lab::Branching, 1, runner);
            request.identity.width = request.identity.height = request.spp = request.seeds = 1;
            const RenderResult r = renderLab(request, limitsOf(setup));
            if (r.ok) seconds.push_back(r.process.cpuSeconds);
        }
        return median(seconds);
    });
}

/// One timed run: the correctness render of the speed scene again, its samples per CPU-second
/// (the kernel's count of the whole sandbox's CPU time, less the start-up), and what it rendered.
struct TimedRun {
    RenderResult result;
    double samples = 0;    ///< width x height x spp x seeds
    double cpuSeconds = 0; ///< of rendering, the start-up taken off
    double samplesPerCpuSecond() const { return samples / cpuSeconds; }
};

TimedRun timedRun(const GraderSetup& setup, const GradingScene& scene, const LabRunner& runner,
                  Lab lab, double startUp) {
    const RenderRequest request =
        correctnessRequest(setup, scene, lab, firstSeedBase(setup), runner);
    TimedRun timed{renderLab(request, limitsOf(setup))};
    if (!timed.result.ok) return timed;
    timed.samples =
        double(request.identity.width) * request.identity.height * request.spp * request.seeds;
    // A run's CPU time below its start-up's is the clock's resolution speaking, not the lab.
    timed.cpuSeconds =
        std::max(timed.result.process.cpuSeconds - startUp, 0.05 * timed.result.process.cpuSeconds);
    return timed;
}

/// The rubric's timed runs of one lab with one runner, in a row (no reference beside them).
struct TimedRuns {
    std::vector<double> samplesPerSecond; ///< per CPU-second, one per run that finished
    RayCounters rays;
    double samples = 0;
    double cpuSeconds = 0, wallSeconds = 0; ///< the runs' own, start-ups included
    bool complete = false;                  ///< every run finished

    double rate() const { return complete ? geometricMean(samplesPerSecond) : 0; }
};

TimedRuns timedRuns(const GraderSetup& setup, const LabRunner& runner, Lab lab,
                    StartUpTimes& startUps) {
    TimedRuns runs;
    const GradingScene* scene = speedScene(setup);
    if (!scene) return runs;
    const LabRunner timed = timedRunner(runner, setup.timing);
    const double startUp = startUpCpuSeconds(setup, timed, *scene, startUps);
    for (int run = 0; run < setup.rubric.speedRuns; ++run) {
        const TimedRun one = timedRun(setup, *scene, timed, lab, startUp);
        if (!one.result.ok) return runs;
        runs.samplesPerSecond.push_back(one.samplesPerCpuSecond());
        for (const RenderedImage& image : one.result.images) runs.rays += image.rays;
        runs.samples += one.samples;
        runs.cpuSeconds += one.result.process.cpuSeconds;
        runs.wallSeconds += one.result.process.seconds;
    }
    runs.complete = true;
    return runs;
}

/// "the machine was busy: ..." when `cpuSeconds` is well below `wallSeconds` on `cores` cores;
/// "" otherwise, or when the cores are not known.
std::string busyNote(double cpuSeconds, double wallSeconds, int cores) {
    if (cores <= 0 || wallSeconds <= 0) return "";
    const double share = cpuSeconds / (wallSeconds * cores);
    if (share >= BusyShare) return "";
    return "the machine was busy: the timed runs had " + std::to_string(std::lround(100 * share)) +
           "% of their " + (cores == 1 ? "core" : std::to_string(cores) + " cores") +
           " (other processes shared them); the figures are CPU time, which that changes little";
}

} // namespace

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
    outcome.studentSamplesPerSecond = runs.rate();
    outcome.solutionSamplesPerSecond = setup.storedSolution.samplesPerCpuSecond[lab];
    if (!correct) {
        check.summary = "speed counts only for a correct lab";
        return outcome;
    }
    check.summary = "graded by the instructor: this build has no reference solutions to time your "
                    "lab against (at least " +
                    fixed(r.minSpeedRatio, 2) +
                    " of the reference's samples per CPU-second on the same machine)";
    if (!(outcome.studentSamplesPerSecond > 0)) return outcome;
    check.details.push_back(
        "yours on this machine: " + significant(outcome.studentSamplesPerSecond, 3) +
        " samples per CPU-second in the grader's timed runs (grading every "
        "lab prints the ratios between them); rays per sample: " +
        raysText(outcome.studentRays));
    const int cores = setup.threads > 0 ? setup.threads : Renderer::defaultThreads();
    if (const std::string busy = busyNote(runs.cpuSeconds, runs.wallSeconds, cores); !busy.empty())
        check.details.push_back(busy);
    const LocalSpeedEstimate e =
        estimateSpeedLocally(r, lab, outcome.studentSamplesPerSecond, outcome.studentRays,
                             setup.storedSolution, setup.kitCpuSecondsPerRay);
    if (!(e.ratio > 0)) {
        check.details.push_back("no stored figures of the reference solutions to estimate your "
                                "speed against (grader/references/lab_figures.json)");
        return outcome;
    }
    check.details.push_back("the reference's rays per sample: " +
                            raysText(setup.storedSolution.rays[lab]));
    const std::string estimate =
        "about " + fixed(e.ratio, 2) + " of the reference's samples per CPU-second, " +
        (e.scaledByRayCost
             ? "its stored figure carried to this machine by the kit's own cost of a ray"
             : "from rays per sample alone (no cost of a ray stored)");
    // The first cause is the summary's where the points are at risk; the details give the rest.
    for (size_t i = e.atRisk ? 1 : 0; i < e.causes.size(); ++i)
        check.details.push_back(e.causes[i]);
    check.atRisk = e.atRisk;
    if (e.atRisk) {
        check.summary = "at risk: your lab would likely lose these points in your instructor's "
                        "grading: " +
                        estimate + ", and at least " + fixed(r.minSpeedRatio, 2) + " is needed; " +
                        e.causes.front();
        check.diagnosis = "likely too slow";
    } else if (e.ratio < r.minSpeedRatio) {
        check.details.push_back(estimate + ": near the threshold, with no cause in its rays or "
                                           "its work per ray; an estimate across machines, which "
                                           "your instructor's grader decides by timing both");
    } else {
        check.details.push_back(estimate + " (an estimate: your instructor's grader times both "
                                           "on one machine)");
    }
    return outcome;
}

namespace {

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
SpeedVerdict judgeSpeed(const Rubric& r, Lab lab, double perSample, double efficiencyRatio,
                        const RaysPerSample& studentRays, const RaysPerSample& solutionRays) {
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

/// Efficiency needs both variances, which the noise check measures for a correct lab only.
bool variancesKnown(const SampleVariances& variances) {
    return variances.student > 0 && variances.solution > 0;
}

/// The log of the variances' ratio, by which a lab judged by efficiency is judged (0 otherwise).
double efficiencyShift(const Rubric& r, Lab lab, const SampleVariances& variances) {
    return r.forLab(lab).speedJudgedBy == SpeedMeasure::Efficiency && variancesKnown(variances)
               ? std::log(variances.solution / variances.student)
               : 0;
}

/// The pairs' ratios, yours over the reference's, in run order.
std::vector<double> pairRatios(const TimedMeasurement& t) {
    std::vector<double> ratios;
    for (size_t i = 0; i < t.student.size(); ++i) ratios.push_back(t.student[i] / t.solution[i]);
    return ratios;
}

/// What the pairs so far say of the ratio against the threshold.
enum class Decision { Faster, Slower, Undecided };

/// The pairs' log ratios (yours over the reference's, plus `shift`, the log of the variances'
/// ratio where efficiency is judged): below log(threshold) with confidence, above with
/// confidence, or neither, by a one-sided Student's t interval at `alpha`.
Decision decide(const std::vector<double>& logRatios, double shift, double threshold,
                double alpha) {
    if (logRatios.size() < 2) return Decision::Undecided;
    const MeanEstimate m = batchMean(logRatios);
    const double margin =
        studentOneSidedCritical(alpha, static_cast<double>(logRatios.size() - 1)) * m.standardError;
    const double estimate = m.mean + shift, limit = std::log(threshold);
    if (estimate + margin < limit) return Decision::Slower;
    if (estimate - margin >= limit) return Decision::Faster;
    return Decision::Undecided;
}

/// At the cap, for a lab still undecided: the same interval with the standard error the
/// machine alone makes, measured by how the reference's runs spread (a pair's log ratio varies
/// by about √2 times one side's log time). The benefit of the doubt is for a lab whose ratio the
/// machine's noise hides; a lab whose own runs vary far more than the reference's (slow in some
/// processes, fast in others) is judged by its ratio against the machine's noise. Returns
/// Slower, or Undecided. `spreadRatio` is set to the lab's spread of log times over the
/// reference's.
Decision decideWithMachineSpread(const std::vector<double>& logRatios, double shift,
                                 double threshold, double alpha, const TimedMeasurement& t,
                                 double& spreadRatio) {
    std::vector<double> studentLogs, solutionLogs;
    for (double v : t.student) studentLogs.push_back(std::log(v));
    for (double v : t.solution) solutionLogs.push_back(std::log(v));
    if (solutionLogs.size() < 2 || logRatios.size() < 2) return Decision::Undecided;
    const double n = static_cast<double>(solutionLogs.size());
    const double machine = batchMean(solutionLogs).standardError * std::sqrt(n); // one run's
    const double own = batchMean(studentLogs).standardError * std::sqrt(n);
    spreadRatio = machine > 0 ? own / machine : 0;
    const double margin = studentOneSidedCritical(alpha, n - 1) * std::sqrt(2.0) * machine /
                          std::sqrt(static_cast<double>(logRatios.size()));
    const double estimate = batchMean(logRatios).mean + shift;
    return estimate + margin < std::log(threshold) ? Decision::Slower : Decision::Undecided;
}

/// The figures every verdict is told with: the summary's samples per CPU-second (the geometric
/// means of each side's runs, whose quotient is the ratio: one set of measurements), the
/// measure, and the details' rays and variances per sample.
void describeTimedRuns(const Rubric& r, Lab lab, double ratio, size_t pairs,
                       const SampleVariances& variances, SpeedOutcome& outcome) {
    CheckResult& check = outcome.check;
    check.summary = significant(outcome.studentSamplesPerSecond, 3) + " samples/s, " +
                    fixed(ratio, 2) + " times the reference solution's " +
                    significant(outcome.solutionSamplesPerSecond, 3) +
                    " (per CPU-second of rendering; the geometric mean of " +
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

/// "the machine was busy: ..." when the timed runs had much less of their cores than their wall
/// time; "" otherwise.
std::string busyNote(const TimedMeasurement& t) {
    return busyNote(t.cpuSeconds, t.wallSeconds, t.timingCores);
}

} // namespace

TimedMeasurement timeLab(const GraderSetup& setup, Lab lab, const SpeedInputs& in,
                         StartUpTimes& startUps) {
    const Rubric& r = setup.rubric;
    TimedMeasurement t;
    const GradingScene* scene = speedScene(setup);
    if (!scene) {
        t.notTimed = "not measured: the rubric's speed scene '" + r.speedScene +
                     "' is not among its correctness scenes";
        t.notTimedDiagnosis = "no speed scene";
        return t;
    }
    const double shift = efficiencyShift(r, lab, in.variances);
    const LabRunner studentRunner = timedRunner(setup.student, setup.timing);
    const LabRunner solutionRunner = timedRunner(setup.solution, setup.timing);
    const TimingLock lock(setup.timing.lockFile);
    if (lock.waitedInVain())
        std::fprintf(stderr,
                     "note: %s was held by another process for %d s: the timed runs go on "
                     "without it, and may share their core\n",
                     setup.timing.lockFile.c_str(), TimingLock::MaxWaitSeconds);
    const double startUp = startUpCpuSeconds(setup, solutionRunner, *scene, startUps);
    t.timingCores = static_cast<int>(setup.timing.cpus.size());
    std::vector<double> logRatios;
    // The series of the lab and of the reference, interleaved A B A B so that a busy spell of
    // a shared machine hits both alike. Pairs are added, speed.runs at a time, until the ratio is
    // known to lie above or below the threshold, or SpeedPairsCap times as many ran.
    for (int look = 0; look < SpeedPairsCap; ++look) {
        for (int run = 0; run < r.speedRuns; ++run) {
            for (const LabRunner* runner : {&studentRunner, &solutionRunner}) {
                const bool isStudent = runner == &studentRunner;
                const TimedRun timed = timedRun(setup, *scene, *runner, lab, startUp);
                if (!timed.result.ok) {
                    t.notTimed = std::string(isStudent ? "the lab " : "the reference ") +
                                 timed.result.failure + " in a timed run";
                    t.notTimedDiagnosis =
                        isStudent ? timed.result.failureKind : "the reference failed";
                    return t;
                }
                (isStudent ? t.student : t.solution).push_back(timed.samplesPerCpuSecond());
                (isStudent ? t.studentWall : t.solutionWall)
                    .push_back(timed.result.process.seconds);
                for (const RenderedImage& image : timed.result.images)
                    (isStudent ? t.studentRays : t.solutionRays) += image.rays;
                (isStudent ? t.studentSamples : t.solutionSamples) += timed.samples;
                t.cpuSeconds += timed.result.process.cpuSeconds;
                t.wallSeconds += timed.result.process.seconds;
                if (isStudent && !in.speedSceneImages.empty()) {
                    std::vector<std::vector<float>> rendered;
                    for (const RenderedImage& image : timed.result.images)
                        rendered.push_back(image.rgb);
                    t.imagesDiffer = t.imagesDiffer || rendered != in.speedSceneImages;
                }
            }
            logRatios.push_back(std::log(t.student.back() / t.solution.back()));
        }
        if (t.imagesDiffer) break;
        // Each look spends its share of alpha (Bonferroni): the chance that a lab at the
        // threshold is failed stays at most alpha over all of them.
        if (decide(logRatios, shift, r.minSpeedRatio, r.speedAlpha / SpeedPairsCap) !=
            Decision::Undecided)
            break;
    }
    return t;
}

SpeedOutcome judgeTimedRuns(const Rubric& r, Lab lab, bool correct,
                            const SampleVariances& variances, const TimedMeasurement& t) {
    SpeedOutcome outcome;
    CheckResult& check = outcome.check;
    check.kind = CheckKind::Speed;
    check.maxScore = r.forLab(lab).points.speed;
    if (!t.timed()) {
        check.summary = t.notTimed;
        check.diagnosis = t.notTimedDiagnosis;
        return outcome;
    }
    const double shift = efficiencyShift(r, lab, variances);
    outcome.studentSamplesPerSecond = geometricMean(t.student);
    outcome.solutionSamplesPerSecond = geometricMean(t.solution);
    outcome.studentRays = raysPerSample(t.studentRays, t.studentSamples);
    outcome.solutionRays = raysPerSample(t.solutionRays, t.solutionSamples);
    const std::vector<double> pairs = pairRatios(t);
    const double ratio = outcome.studentSamplesPerSecond / outcome.solutionSamplesPerSecond;
    // Efficiency, 1/(variance per sample x time per sample), from the noise check's variances
    // (the same scene) and these samples per CPU-second.
    outcome.efficiencyRatio =
        variancesKnown(variances) ? ratio * variances.solution / variances.student : 0;
    describeTimedRuns(r, lab, ratio, pairs.size(), variances, outcome);
    if (const std::string busy = busyNote(t); !busy.empty()) check.details.push_back(busy);
    if (!correct) {
        check.summary += "; speed counts only for a correct lab";
        return outcome;
    }
    if (t.imagesDiffer) {
        check.summary += "; the timed runs rendered other images than the same seeds did in the "
                         "correctness renders, and speed counts only for a lab that renders alike "
                         "when timed";
        check.diagnosis = "wrong image in the timed runs";
        return outcome;
    }
    if (r.forLab(lab).speedJudgedBy == SpeedMeasure::Efficiency && !variancesKnown(variances)) {
        // Cannot happen for a correct lab (the noise check measures both); said if it does.
        check.summary += "; efficiency unknown: the variances were not measured";
        check.diagnosis = "efficiency unknown";
        return outcome;
    }
    std::vector<double> logRatios;
    for (double p : pairs) logRatios.push_back(std::log(p));
    const Decision decision =
        decide(logRatios, shift, r.minSpeedRatio, r.speedAlpha / SpeedPairsCap);
    SpeedVerdict verdict = judgeSpeed(r, lab, ratio, outcome.efficiencyRatio, outcome.studentRays,
                                      outcome.solutionRays);
    double spreadRatio = 0;
    if (decision == Decision::Undecided && !verdict.passed &&
        decideWithMachineSpread(logRatios, shift, r.minSpeedRatio, r.speedAlpha / SpeedPairsCap, t,
                                spreadRatio) == Decision::Slower) {
        // The lab's own runs vary, not the machine: no benefit of the doubt.
        verdict.details.push_back(
            "your lab's timed runs vary from run to run " + fixed(spreadRatio, 1) +
            " times as much as the reference's (which vary only with the machine): judged "
            "against the machine's variation, the ratio " +
            fixed(ratio, 2) + " is below " + fixed(r.minSpeedRatio, 2) +
            " with confidence. Does your lab do more work in some runs than in others?");
    } else if (decision == Decision::Undecided && !verdict.passed) {
        // After the last pairs, neither above nor below the threshold with confidence: the lab
        // is given the benefit of the doubt, and told so.
        verdict = {};
        verdict.passed = true;
        verdict.details.push_back(
            "after " + std::to_string(pairs.size()) + " pairs the ratio could not be told from " +
            fixed(r.minSpeedRatio, 2) + " with confidence: the benefit of the doubt is yours");
    }
    check.passed = verdict.passed;
    check.score = check.passed ? check.maxScore : 0;
    check.details.insert(check.details.end(), verdict.details.begin(), verdict.details.end());
    check.diagnosis = std::move(verdict.diagnosis);
    return outcome;
}

TimedFigures timedFigures(const GraderSetup& setup, const LabRunner& runner, Lab lab,
                          StartUpTimes& startUps) {
    const TimedRuns runs = timedRuns(setup, runner, lab, startUps);
    return {runs.rate(), raysPerSample(runs.rays, runs.samples)};
}

} // namespace pathlab::grader
