#pragma once
/// The lab tests' renders and verdicts. A check renders one scene with the lab under test
/// (test::renderLabUnderTest) and, when it fails, says so once: what was rendered, with which
/// --max-depth or --continue-prob, what came out and what was expected, and the likely step of
/// the lab when the grader's diagnosis (grader/src/diagnosis/diagnosis.h) recognises the value.

#include "checks/expectation.h"

#include "runner/headless_render.h"

#include "pathlab/render/lab_registry.h"

#include <cstdint>
#include <string>
#include <vector>

namespace pathlab::test {

/// One render of a lab for a lab test.
struct LabRun {
    Lab lab;
    std::string scene; ///< file name in models/, e.g. "furnace.ecs"
    HeadlessResult result;

    /// E.g. "lab 3 (importance) on furnace.ecs with --max-depth 3, 48x48 pixels at 32 spp,
    /// seed 1".
    std::string description() const;
};

/// Renders models/`scene` with the lab under test, size×size pixels at `spp` samples per pixel
/// from a fixed seed; `options` are further viewer options, e.g. {"--max-depth", "5"}.
LabRun renderLab(Lab lab, const std::string& scene, int size, int spp, uint64_t seed,
                 const std::vector<std::string>& options = {});

/// No pixel received a NaN or infinite sample.
void checkFinite(const LabRun& run);

/// The image mean is the furnace's analytic value, from the scene's furnace model. The furnaces
/// are grey, so the three channels carry the same light and their average is tested: a
/// two-sided z-test at alpha 1e-5 (|z| < 4.42), the standard error no less than 5e-4 of the
/// value (the facets' heavy tail, lab_checks.cpp), and, so that a large standard error cannot
/// hide a bias, within 2%.
void checkFurnace(const LabRun& run);

/// The same for a furnace the diagnosis has no model of, with its value and formula.
void checkFurnace(const LabRun& run, double expected, const std::string& formula);

/// Whether the lab's furnace.ecs and mirror_furnace.ecs, rendered as their tests render them
/// (labs 1-3 at --max-depth 3, lab 4 at --continue-prob 0.8), pass checkFurnace: a scene's likely
/// cause that holds only where they do is told only then.
bool diagnosingFurnacesAgree(Lab lab);

/// Per channel, the whole image's mean agrees with the stored reference's (region 0): a
/// two-sided z-test at alpha 1e-5 (|z| < 4.42) of the difference, with the render's and the
/// reference's standard errors combined.
void checkAgainstReference(const LabRun& run, const grader::Expectation& reference);

/// Region by region, as the grader compares a scene: `runs` are independent renders (seeds) of
/// one scene, and each region of their images (the whole image and each of `tiles` × `tiles`
/// tiles), per channel, is compared with the reference by a two-sided Student t-test of the
/// renders' mean (the spread between renders is the standard error, which holds where a few
/// rare bright samples make the pixels' own variances mislead), the reference's standard error
/// combined, and a relative floor of 1e-5 for regions that every sample sees alike; alpha 1e-5
/// divided among the tests (Bonferroni); and a difference of at least MinRelativeDifference. A
/// failure names the tiles that differ and then `likelyCause`, the grader's words for what this
/// scene shows.
void checkRegionsAgainstReference(const std::vector<LabRun>& runs,
                                  const grader::Expectation& reference, int tiles,
                                  const std::string& likelyCause);

/// Each region and channel that check compares (flat [region][channel]): its t, and its mean's
/// difference from the reference's relative to the reference's.
struct RegionDifference {
    double t = 0, relative = 0;
};
std::vector<RegionDifference> regionDifferences(const std::vector<LabRun>& runs,
                                                const grader::Expectation& reference, int tiles);

/// The critical value of |t|, and the smallest relative difference that counts: the grader's own
/// check has its seeds and retries for small differences; these tests are for bugs that change a
/// region by tens of percent, and a heavy-tailed lab's t over 16 renders is only roughly
/// Student's (its few bright samples skew it).
double regionCritical(size_t renders, size_t tests);
constexpr double MinRelativeDifference = 0.05;

/// Whether a region and channel differs: beyond both.
bool differs(const RegionDifference& d, double critical);

} // namespace pathlab::test
