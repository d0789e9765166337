#include "lab_checks.h"

#include "catch.h"
#include "statistics.h"
#include "test_support.h"

#include "diagnosis/diagnosis.h"

#include "pathlab/todo.h"

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <optional>
#include <sstream>

namespace pathlab::test {

namespace {

/// Every check's significance: a correct lab fails one with probability at most this.
constexpr double Alpha = 1e-5;

/// A floor under a furnace's standard error, relative to its value. On the tessellated sphere,
/// next-event estimation between points of neighbouring facets has infinite variance (a 1/r²
/// geometry term whose cosines do not vanish at the shared edge): a rare sample is huge, so a
/// typical seed sits a little low with a standard error that does not show it. Over 300 seeds of
/// each check, labs 1 and 3 in furnace and furnace_a08 erred from -7e-4 to +5e-3 of the value,
/// with z down to -5.5 without the floor and within ±1.5 with it; known bugs are 1.6% away or
/// more. The floor also covers float rounding where every sample is alike (mirror_furnace).
constexpr double FurnaceErrorFloor = 5e-4;

/// What went wrong when some pixel received a NaN or infinite sample, with the likely cause;
/// "" when none did. That failure is reported instead of any statistic of the image.
std::string nonfiniteProblem(const LabRun& run) {
    const RenderStats& s = run.result.stats;
    if (s.nonfinitePixels == 0) return "";
    return run.description() + ": " + std::to_string(s.nonfinitePixels) + " of " +
           std::to_string(s.width * s.height) +
           " pixels received a NaN or infinite sample. Likely cause: " +
           grader::likelyNonfiniteCause(run.lab) + ".";
}

/// The furnace model of a scene rendered as `run` was; none for a scene without one.
std::optional<grader::FurnaceModel> furnaceModelOf(const std::string& scene, const LabRun& run) {
    const RenderStats& s = run.result.stats;
    return grader::furnaceModel(std::filesystem::path(scene).stem().string(), s.maxDepth,
                                s.continueProb);
}

/// The furnace's mean (the channels' average: the walls are grey, so the channels are equal
/// sample by sample) and its standard error.
grader::FurnaceObservation observe(const grader::FurnaceModel& model, const LabRun& run) {
    const Estimate e = estimateOf(run.result);
    return {model, average(e.mean), average(e.standardError)};
}

/// The furnaces the diagnosis knows that tell the likeliest bugs apart: one alone may fit
/// several (the mirror furnace shows Le both without emission after specular bounces and
/// without any bounce), the two together tell them apart, as in the grader.
const char* const DiagnosingFurnaces[] = {"furnace.ecs", "mirror_furnace.ecs"};

/// The known bugs that fit the furnace value `own` and those of the other diagnosing furnaces
/// rendered alike, as a sentence; "" when none does.
std::string likelyCauses(const LabRun& run, const grader::FurnaceObservation& own) {
    std::vector<grader::FurnaceObservation> observations = {own};
    std::ostringstream others;
    others << std::setprecision(5);
    const RenderStats& s = run.result.stats;
    for (const char* other : DiagnosingFurnaces) {
        if (other == run.scene) continue;
        const LabRun alike = renderLab(run.lab, other, s.width, s.spp, s.seed,
                                       {"--max-depth", std::to_string(s.maxDepth),
                                        "--continue-prob", std::to_string(s.continueProb)});
        if (alike.result.stats.nonfinitePixels > 0) continue;
        const grader::FurnaceModel model = *furnaceModelOf(other, alike);
        observations.push_back(observe(model, alike));
        others << " and " << other << " rendered alike (" << observations.back().observed
               << ", where a correct lab gives " << grader::correctFurnaceValue(run.lab, model)
               << ")";
    }
    const std::vector<std::string> causes = grader::likelyFurnaceCauses(
        run.lab, observations, todoReported(static_cast<int>(run.lab) + 1));
    if (causes.empty()) return "";
    std::ostringstream text;
    text << " This value" << others.str() << (observations.size() > 1 ? " match: " : " matches: ");
    for (size_t i = 0; i < causes.size(); ++i) text << (i == 0 ? "" : "; or: ") << causes[i];
    text << ".";
    return text.str();
}

void checkFurnaceValue(const LabRun& run, double expected, const std::string& formula,
                       const std::optional<grader::FurnaceModel>& model) {
    if (const std::string problem = nonfiniteProblem(run); !problem.empty()) {
        FAIL_CHECK(problem);
        return;
    }
    const grader::FurnaceObservation own = observe(model.value_or(grader::FurnaceModel{}), run);
    const double mean = own.observed, standardError = own.standardError;
    const double allowed = std::hypot(standardError, FurnaceErrorFloor * expected);
    const double z = (mean - expected) / allowed;
    const double critical = normalCritical(Alpha);
    if (std::fabs(z) < critical && std::fabs(mean - expected) < 0.02 * expected) return;
    // z is over the standard error and the floor together, so the message shows both: a mirror
    // furnace, whose samples are all alike, has a standard error of 0.
    std::ostringstream message;
    message << std::setprecision(5) << run.description() << ": observed " << mean << " ± "
            << standardError << " (standard error), expected " << expected << " = " << formula
            << "; z = (observed - expected) / " << allowed << " = " << z
            << " (the standard error and a floor of " << FurnaceErrorFloor
            << " of the expected value for the scene's approximations, together; a correct lab "
               "gives |z| < "
            << critical << ", within 2%).";
    if (model) message << likelyCauses(run, own);
    FAIL_CHECK(message.str());
}

} // namespace

std::string LabRun::description() const {
    const RenderStats& s = result.stats;
    std::ostringstream text;
    text << "lab " << static_cast<int>(lab) + 1 << " (" << labName(lab) << ") on " << scene
         << " with ";
    if (isDepthLimited(lab))
        text << "--max-depth " << s.maxDepth;
    else
        text << "--continue-prob " << s.continueProb;
    text << ", " << s.width << "x" << s.height << " pixels at " << s.spp << " spp, seed " << s.seed;
    return text.str();
}

LabRun renderLab(Lab lab, const std::string& scene, int size, int spp, uint64_t seed,
                 const std::vector<std::string>& options) {
    std::vector<std::string> arguments = {"-c",
                                          modelPath(scene),
                                          "--size",
                                          std::to_string(size),
                                          std::to_string(size),
                                          "--spp",
                                          std::to_string(spp),
                                          "--seed",
                                          std::to_string(seed),
                                          "--lab",
                                          std::string(labName(lab))};
    arguments.insert(arguments.end(), options.begin(), options.end());
    return {lab, scene, renderLabUnderTest(arguments)};
}

void checkFinite(const LabRun& run) {
    if (const std::string problem = nonfiniteProblem(run); !problem.empty()) FAIL_CHECK(problem);
}

void checkFurnace(const LabRun& run) {
    const std::optional<grader::FurnaceModel> model = furnaceModelOf(run.scene, run);
    if (!model) FAIL("the diagnosis has no furnace model of " << run.scene);
    checkFurnaceValue(run, grader::correctFurnaceValue(run.lab, *model),
                      grader::furnaceFormula(run.lab, *model), model);
}

void checkFurnace(const LabRun& run, double expected, const std::string& formula) {
    checkFurnaceValue(run, expected, formula, std::nullopt);
}

void checkAgainstReference(const LabRun& run, const grader::Expectation& reference) {
    if (const std::string problem = nonfiniteProblem(run); !problem.empty()) {
        FAIL_CHECK(problem);
        return;
    }
    const Estimate e = estimateOf(run.result);
    const double critical = normalCritical(Alpha);
    const char* channels[3] = {"red", "green", "blue"};
    bool agrees = true;
    std::ostringstream comparison;
    comparison << std::setprecision(5);
    for (int c = 0; c < 3; ++c) {
        const double se = std::hypot(e.standardError[c], reference.standardError[c]);
        const double z = (e.mean[c] - reference.mean[c]) / se;
        agrees = agrees && std::fabs(z) < critical;
        comparison << (c == 0 ? "" : "; ") << channels[c] << " " << e.mean[c] << " ± "
                   << e.standardError[c] << " against " << reference.mean[c] << " ± "
                   << reference.standardError[c] << " (z = " << z << ")";
    }
    if (agrees) return;
    FAIL_CHECK(run.description() << ": the image mean differs from the reference solution's ("
                                 << reference.solution << ", " << reference.seeds << " seeds at "
                                 << reference.spp << " spp): " << comparison.str()
                                 << "; a correct lab gives |z| < " << std::setprecision(5)
                                 << critical
                                 << " in every channel. This lab's furnace tests name likely "
                                    "causes.");
}

} // namespace pathlab::test
