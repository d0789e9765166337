#pragma once
/// The side-by-side replay: a lab's paths against the reference solution's on the same pixel
/// and the same random numbers, and the first vertex where they part.

#include "pathlab/inspect/inspected_path.h"

#include <optional>
#include <string>

namespace pathlab {

/// Where, and why, a lab's path first differs from the reference's.
struct PathDivergence {
    size_t sample = 0; ///< index into the inspections' samples
    int vertex = -1;   ///< the vertex (of the lab's path) where it shows
    std::string kind;  ///< emission, depth, roulette, pick, probability, direct-light, ray,
                       ///< draw-order, value
    std::string step;  ///< the handout step, "lab4.2"; empty where no step is the lab's own
    std::string text;  ///< one sentence for the student, naming the vertex and the values
};

struct PathComparison {
    size_t samplesCompared = 0;
    /// The first difference; none when every sample's path and value agree.
    std::optional<PathDivergence> divergence;
    /// False when the lab draws its random numbers in another order or number than the
    /// reference: a valid estimator may, and its paths then cannot be compared draw by draw.
    bool comparable = true;
};

/// Compares sample by sample, in the order the lab made its calls: first which calls (a ray
/// traced, the direct light asked for, the path ended), then, where the calls agree, the weights
/// the lab gave each vertex's light. Both inspections must be of the same pixel, seed and
/// parameters.
PathComparison comparePaths(const PixelInspection& lab, const PixelInspection& reference);

/// The comparison in a line or two, for a terminal, a report or a grader's feedback.
std::string describeComparison(const PathComparison& comparison, const PixelInspection& lab);

} // namespace pathlab
