#include "checks/lobe_check.h"

#include "checks/glossy_furnace_scene.h"
#include "checks/run_limits.h"
#include "isolation/render_run.h"

#include "pathlab/warp/phong_lobe_check.h"

#include <cstdio>

namespace pathlab::grader {

namespace {

/// Fails `correctness` with `lines` first in its details, keeping a statistical failure after.
void fail(CheckResult& correctness, std::vector<std::string> lines, const std::string& summary) {
    if (!correctness.passed) lines.push_back("also: " + correctness.summary);
    correctness.details.insert(correctness.details.begin(), lines.begin(), lines.end());
    correctness.passed = false;
    correctness.score = 0;
    correctness.summary = summary;
    correctness.diagnosis = LobeDiagnosis;
}

} // namespace

void addLobeVerdict(const GraderSetup& setup, Lab lab, CheckResult& correctness) {
    // A seed of this submission's own: the inputs differ from one submission to another, and
    // stay the same when the same lab is graded again.
    const uint64_t seed = labVariantSeed(setup, lab);
    const LabToolRun run = dumpLobe(setup.student, lab, seed, setup.scratch, limitsOf(setup));
    const std::string number = std::to_string(labNumber(lab));
    if (!run.ok) {
        fail(correctness, {"the lobe check ran sampleLobe and lobePdf, and the lab " + run.failure},
             "the lobe check's run of sampleLobe and lobePdf failed: " + run.failureKind);
        return;
    }
    LobeDump dump;
    std::string problem;
    const std::vector<float> exponents = lobeCheckExponents(seed);
    if (!readLobeDump(run.bytes, exponents, dump, problem)) {
        fail(correctness,
             {"the lobe check could not read what the lab's process wrote: " + problem},
             "the lobe check's output could not be read");
        return;
    }
    const PhongLobeFinding finding =
        checkAgainstPhongLobe(dump, seed, LobeCheckFalseFailRate, labNumber(lab));
    char how[260];
    std::snprintf(how, sizeof how,
                  "%u directions at each of the exponents %.3g, %.3g and %.3g (drawn for this "
                  "submission), and the density at %u points each; right routines fail with "
                  "probability %g",
                  LobeDumpSamples, exponents[0], exponents[1], exponents[2], LobeDumpDensityPoints,
                  LobeCheckFalseFailRate);
    if (finding.passed) {
        correctness.details.push_back("the lobe check: sampleLobe and lobePdf follow the Phong "
                                      "lobe (" +
                                      std::string(how) + ")");
        return;
    }
    std::vector<std::string> lines = finding.problems;
    lines.push_back("found by the lobe check (" + std::string(how) +
                    "): `make warptest` shows your pair's samples against your density");
    // The steps the problems name, in order.
    std::string steps;
    for (const char* step : {".1", ".2"}) {
        const std::string todo = "TODO lab" + number + step;
        for (const std::string& p : finding.problems)
            if (p.find(todo) != std::string::npos) {
                steps += (steps.empty() ? "" : ", ") + todo;
                break;
            }
    }
    fail(correctness, lines, std::string(LobeDiagnosis) + " (" + steps + ")");
}

} // namespace pathlab::grader
