#pragma once
/// Whether a lab's images come from tracing paths. The correctness check compares means of the
/// image and of its tiles; a lab could return those means from a table (the shipped references
/// hold them) and trace nothing. Three properties every path-traced estimate has and a table
/// lacks, each against what the reference solutions show on the same scene:
///  - its pixels vary from seed to seed, where every lab's reference's do;
///  - it traces bounce rays, where every lab's reference does;
///  - its image has the detail the reference image has inside each tile.
/// Each is judged only where the reference makes it meaningful (a mirror furnace has no
/// variance; a furnace has no detail), with a margin far beyond sampling noise.

#include <string>
#include <vector>

namespace pathlab::grader {

/// What one scene's renders of a lab show, beside the reference's.
struct PathEvidence {
    double variance = 0; ///< the lab's per-sample variance (trimmedSampleVariance)
    /// The least of the reference solutions', one per lab (a valid lab may be as quiet as the
    /// quietest estimator), at the same seeds and spp.
    double referenceVariance = 0;
    double bounceRays = 0;           ///< the lab's bounce rays per sample
    double referenceBounceRays = -1; ///< the least of the reference solutions'; < 0: not known
    /// The lab's mean image over its seeds, and the reference image, linear RGB of
    /// width x height; `referenceNoise`: the variance of one pixel of the reference image.
    std::vector<float> meanImage, referenceImage;
    int width = 0, height = 0, tiles = 1;
    double referenceNoise = 0;
};

/// The share of the reference image's detail inside the tiles that the lab's image has: the
/// slope of the lab's pixels, less their tile's mean, on the reference's, less theirs. About 1
/// for a rendered image, 0 for one that is flat inside each tile; -1 where the reference has no
/// detail to speak of there (a furnace), beyond its own noise.
double detailInsideTiles(const PathEvidence& evidence);

/// "" where the images look traced; else one sentence for the student saying what is missing,
/// with the figures, which feedback shows for a public scene only.
std::string missingPathEvidence(const PathEvidence& evidence);

/// The diagnosis of a lab whose images do not come from paths.
inline constexpr const char* NotTracedDiagnosis = "the image does not come from tracing paths";

} // namespace pathlab::grader
