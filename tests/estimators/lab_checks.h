#pragma once
/// The lab tests' renders and verdicts. A check renders one scene with the lab under test
/// (test::renderLabUnderTest) and, when it fails, says so once: what was rendered, with which
/// --max-depth or --continue-prob, what came out and what was expected, and the likely step of
/// the lab when the grader's diagnosis (grader/src/diagnosis/diagnosis.h) recognises the value.

#include "checks/expectation.h"

#include "runner/headless_render.h"

#include "pathlab/lab_registry.h"

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

/// Per channel, the whole image's mean agrees with the stored reference's (region 0): a
/// two-sided z-test at alpha 1e-5 (|z| < 4.42) of the difference, with the render's and the
/// reference's standard errors combined.
void checkAgainstReference(const LabRun& run, const grader::Expectation& reference);

} // namespace pathlab::test
