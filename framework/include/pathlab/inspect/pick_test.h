#pragma once
/// The pick test of a lab that picks one component per hit (labs 2-4): over many replayed paths,
/// how often it went on by each component at each material, against the probability it divided
/// that component's ray by. A lab that picks with one probability and divides by another fails
/// it, wherever its image's mean happens to land; a lab that picks by any rule and divides by
/// that rule's probability passes.

#include "pathlab/inspect/inspected_path.h"
#include "pathlab/warp/chi_square_fit.h"

#include <string>
#include <vector>

namespace pathlab {

/// One component's picks at one material.
struct ComponentPicks {
    std::string component;            ///< diffuse, mirror, refraction
    int picked = 0;                   ///< vertices the lab went on from by it
    std::vector<float> dividedBy;     ///< what it divided by, each time
    float claimedProbability() const; ///< the median of dividedBy
};

/// The picks at one material, and their chi-square test.
struct MaterialPicks {
    Material material;
    std::string name; ///< its components, as the inspector writes them: "Kd 0.5 Ks 0.9"
    int visits = 0;   ///< the vertices where the lab chose (found, below maxDepth, measured)
    int ended = 0;    ///< of them, where no ray went on
    std::vector<ComponentPicks> components;
    double claimedTotal = 0; ///< the components' claimed probabilities added
    ChiSquareFit fit;        ///< the counts against visits × claimed (and the rest for `ended`)
};

struct PickTestResult {
    /// False for a lab that branches (lab 1: a ray for every component, nothing picked), one that
    /// went on by no component (a stub), or where no material was visited often enough: nothing
    /// was tested.
    bool applies = false;
    int minVisits = 0;
    double alpha = 0;     ///< the chance a right lab fails, over all the materials tested
    double alphaEach = 0; ///< per material (Šidák)
    std::vector<MaterialPicks> materials; ///< the most visited first
    bool passed = true;
    /// One line per material that fails: "at Kt 0.9 Ks 0.1 (412 visits) you went on by
    /// refraction with frequency 0.33 and divided by 0.9".
    std::vector<std::string> problems;
};

/// Tallies every vertex of `inspections` (one lab's replays) by material and tests each
/// material visited at least `minVisits` times. A vertex counts where the lab could choose: its
/// ray found a surface with a component that is not black, below maxDepth for a depth-limited
/// lab. Where mirror and refraction are one ray (total internal reflection), the pick is the
/// component the material has, and the vertex is left out where it has both. What a component's
/// rays were divided by is the median of the divisions measured.
PickTestResult testPicks(const std::vector<PixelInspection>& inspections, double alpha = 0.001,
                         int minVisits = 100);

/// The result in words: what was tested, and each material's frequencies against what the lab
/// divided by.
std::string describePickTest(const PickTestResult& result);

} // namespace pathlab
