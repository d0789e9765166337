#pragma once
/// A lab's lobe routines judged against the lobe handout 05 derives, from what they gave for
/// the grader's inputs (lobe_dump.h): sampleLobe's directions by the warp test with the Phong
/// lobe's own density in place of the lab's and by their spread through the lobe's CDF, and
/// lobePdf's values against that density point by point. Unlike the students' warp test (their
/// samples against their own density, which a pair of another shape would pass), this tells whether
/// they sample the lobe the BRDF has.

#include "pathlab/warp/lobe_dump.h"
#include "pathlab/warp/warp_test.h"

#include <string>
#include <vector>

namespace pathlab {

/// The normalised Phong lobe about z: (n + 1)/(2π) · cosⁿ α, 0 below its plane.
double phongLobeDensity(const Vec3& direction, double exponent);

struct PhongLobeFinding {
    bool passed = true;
    /// One line per problem, naming the step it is in ("TODO lab5.1" for sampleLobe's,
    /// "TODO lab5.2" for lobePdf's, of lab `labNumber`).
    std::vector<std::string> problems;
    std::vector<WarpTestResult> sampling; ///< per exponent: the directions against the lobe
};

/// Judges `dump`, made for `seed`. `alpha`: the chance that right routines fail, shared among
/// the exponents' chi-square tests (Šidák): per exponent, the directions counted over the
/// sphere's cells against the lobe's density, and, mapped through the lobe's CDF to
/// (cos^(n+1) α, φ/2π), counted over 50 × 50 cells against a uniform spread, which sees inside
/// the first test's cells (a sampler of few distinct directions matches their counts and fails
/// this). lobePdf's values are exact up to float rounding and are held to 0.2%.
PhongLobeFinding checkAgainstPhongLobe(const LobeDump& dump, uint64_t seed, double alpha,
                                       int labNumber);

} // namespace pathlab
