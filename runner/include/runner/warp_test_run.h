#pragma once
/// `viewer --warp-test`: the warp test (pathlab/warp/warp_test.h) of a lab's glossy lobe, its
/// sampleLobe against its lobePdf, at a few of the lobe's exponents, and its picture.

#include "runner/lab_tables.h"

#include "pathlab/render/lab_registry.h"
#include "pathlab/warp/lobe_dump.h"
#include "pathlab/warp/warp_test.h"

#include <string>
#include <vector>

namespace pathlab {

/// The chance that a right routine fails any of the exponents' tests: each is run at the Šidák
/// share of it.
constexpr double WarpTestFalseFailRate = 0.001;

struct LabWarpTest {
    float exponent = 0;
    WarpTestResult result;
};

struct LabWarpTests {
    Lab lab{};
    Implementation implementation{};
    std::vector<LabWarpTest> exponents;
    bool passed = false;
};

/// The lab's sampleLobe and lobePdf in `implementation`; InputError for a lab that writes none,
/// naming the labs that do.
LobeRoutines lobeRoutinesToTest(Lab lab, Implementation implementation);

/// The warp test of `lab`'s lobe in `implementation` at each of WarpTestExponents, `samples`
/// samples each from `seed`. The lab's code is watched as a render's is: a routine that finishes
/// no sample for `watchdogSeconds` ends the process with a line naming it (0: never), one that
/// crashes it says so. Throws InputError for a lab that writes no lobe.
LabWarpTests runLabWarpTests(Lab lab, Implementation implementation, uint64_t seed,
                             uint64_t samples, double watchdogSeconds);

/// viewer --lobe-dump: what `lab`'s sampleLobe gives for lobeDumpNumbers(seed) and its lobePdf
/// at lobeCheckDirections(seed, ...), at each of lobeCheckExponents(seed)
/// (pathlab/warp/lobe_dump.h), written to `path` for the grader to judge. Watched as
/// runLabWarpTests is.
void writeLobeDump(const std::string& path, Lab lab, Implementation implementation, uint64_t seed,
                   double watchdogSeconds);

/// One line per exponent: "exponent 12: passed: chi-square ..." or its problems; and the verdict.
std::string describeLabWarpTests(const LabWarpTests& tests);

/// The three panels the picture and the window draw of one exponent's result, left to right.
enum class WarpPanel { Observed, Expected, Difference };

/// The top of the counts' heat scale: the largest count or expectation of any cell (at least 1).
double warpCountScale(const WarpTestResult& result);

/// The RGBA8 colour of `cell` in `panel`: the counts and the expectations on one heat scale up
/// to `scale` (warpCountScale), their difference in standard deviations of the count on the
/// diverging palette (±5 at its ends).
void warpCellColour(const WarpTestResult& result, WarpPanel panel, size_t cell, double scale,
                    unsigned char* rgba);

/// The picture: one row per exponent, its observed counts and the density's expected counts side
/// by side over the cells (θ down from the lobe's axis, φ across), on the same colour scale, and
/// their difference in standard deviations (blue: fewer samples than expected, red: more).
void writeWarpTestImage(const std::string& path, const LabWarpTests& tests);

} // namespace pathlab
