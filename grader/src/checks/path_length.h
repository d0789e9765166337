#pragma once
/// Whether a Russian-roulette lab honours ctx.continueProb, told by its path lengths. A lab that
/// continues with a constant of its own and divides by the same constant is still unbiased, so
/// no mean radiance reveals it; its path lengths do. In a closed diffuse furnace every ray hits
/// a surface with Kd, so a lab that continues with probability q at every hit traces on average
/// q/(1-q) bounce rays per sample: 4 at q = 0.8, 1 at q = 0.5.

#include <string>
#include <vector>

namespace pathlab::grader {

/// One render of lab 4 in a diffuse furnace: its continueProb and the bounce rays per sample it
/// traced (rays_per_sample.h).
struct PathLengthObservation {
    double continueProb = 0;
    double bounceRays = 0;
};

/// q/(1-q): the mean bounce rays per sample of roulette with continue probability q in a closed
/// diffuse furnace.
double expectedBounceRays(double continueProb);

/// Why the observations show that the lab ignores ctx.continueProb (two continueProbs, paths
/// of the same length), as a cause that names the step; "" when they do not.
std::string ignoredContinueProb(const std::vector<PathLengthObservation>& observations);

/// A note for a lab whose paths lengthen with continueProb but not as continuing with that
/// probability at every hit makes them (a few forced bounces first, say): not wrong in the mean,
/// and not what lab 4 asks; "" when they match.
std::string pathLengthNote(const std::vector<PathLengthObservation>& observations);

} // namespace pathlab::grader
