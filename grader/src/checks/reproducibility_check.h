#pragma once
/// The reproducibility part of the correctness check: the same seed must give the same image in
/// any process and at any thread count, as it does for every lab that draws its random numbers
/// from ctx.sampler and shares nothing between the render threads.

#include "checks/grader_setup.h"

#include <string>
#include <vector>

namespace pathlab::grader {

/// One image the correctness check rendered: where, with which seed and at how many threads.
struct SeedImage {
    const GradingScene* scene = nullptr;
    uint64_t seed = 0;
    int threads = 0;
    std::vector<float> rgb;
};

/// What the reproducibility renders found.
struct Reproducibility {
    bool reproducible = true;
    /// Why not, in sentences a student can act on (empty when reproducible, or when a render of
    /// its own failed: a lab that crashes or hangs is told so by the correctness renders).
    std::vector<std::string> details;
};

/// Renders `seen`'s scene and seed again in two fresh processes, at 1 thread and at 2, and
/// compares the three images bit for bit. A lab that draws its own random numbers (rand(), a
/// <random> engine of its own, thread-local or not) or keeps state shared between the render
/// threads gives different images; a lab that follows the handout's conventions never does.
Reproducibility checkReproducibility(const GraderSetup& setup, Lab lab, const SeedImage& seen);

/// The feedback's diagnosis for a lab whose images are not reproducible.
inline constexpr const char* NotReproducibleDiagnosis = "not reproducible from the seed";

} // namespace pathlab::grader
