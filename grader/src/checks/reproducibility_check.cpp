#include "checks/reproducibility_check.h"

#include "checks/run_limits.h"

#include <cstring>

namespace pathlab::grader {

namespace {

/// Bit for bit, so that NaN equals NaN and -0 differs from 0: the renderer adds a pixel's
/// samples in the same order whatever the threads, so a lab that follows the conventions gives
/// the same bits, not merely close values.
bool sameBits(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0);
}

/// How many of the image's pixels differ, as "N of M pixels".
std::string differingPixels(const std::vector<float>& a, const std::vector<float>& b) {
    size_t differing = 0;
    for (size_t i = 0; i + 2 < a.size() && i + 2 < b.size(); i += 3)
        if (std::memcmp(&a[i], &b[i], 3 * sizeof(float)) != 0) ++differing;
    return std::to_string(differing) + " of " + std::to_string(a.size() / 3) + " pixels";
}

std::string threadsText(int threads) {
    return threads > 0 ? std::to_string(threads) + (threads == 1 ? " thread" : " threads")
                       : std::string("all cores");
}

} // namespace

Reproducibility checkReproducibility(const GraderSetup& setup, Lab lab, const SeedImage& seen) {
    const Rubric& r = setup.rubric;
    const GradingScene& scene = *seen.scene;
    const LabParameters parameters =
        scene.parameters.value_or(LabParameters{r.maxDepth, r.continueProb});
    // Two threads alone do not make a lab's own random numbers differ: on a busy machine one
    // thread may render every tile of a small image before the other starts. The tiles in
    // reverse order do, on any machine: a lab's own generator or shared variable then meets the
    // pixels in another order.
    struct Render {
        int threads;
        bool reverseTiles;
        std::vector<float> rgb;
        std::string how() const {
            return "on " + threadsText(threads) +
                   (reverseTiles ? " (tiles last to first)" : " (tiles in order)");
        }
    };
    std::vector<Render> renders = {{1, false, {}}, {2, true, {}}};
    for (Render& render : renders) {
        RenderRequest request{
            &setup.student,
            scene.path,
            requestedIdentity(setup.student, lab, parameters, seen.seed, r.width, r.height),
            r.forLab(lab).correctnessSpp,
            1,
            render.threads,
            setup.scratch};
        request.reverseTiles = render.reverseTiles;
        const RenderResult result = renderLab(request, limitsOf(setup));
        if (!result.ok) return {}; // the correctness renders tell a crash or a hang
        render.rgb = result.image();
    }

    std::string difference;
    if (!sameBits(renders[0].rgb, renders[1].rgb))
        difference = "rendered " + renders[0].how() + " and " + renders[1].how() + ", " +
                     differingPixels(renders[0].rgb, renders[1].rgb) + " differ";
    else if (!sameBits(seen.rgb, renders[0].rgb))
        difference = "in two runs, on " + threadsText(seen.threads) + " and " + renders[0].how() +
                     ", " + differingPixels(seen.rgb, renders[0].rgb) + " differ";
    if (difference.empty()) return {};

    Reproducibility outcome;
    outcome.reproducible = false;
    outcome.details.push_back(
        "the same seed (" + std::to_string(seen.seed) + ") gave different images of " +
        (scene.hidden ? scene.name : scene.reference.scene) + ": " + difference);
    outcome.details.push_back(
        "likely cause: " + std::string(NotReproducibleDiagnosis) +
        ": the lab draws random numbers that do not come from ctx.sampler (rand(), a <random> "
        "engine or std::random_device of its own, thread-local or not), or keeps state that the "
        "render threads share (a static or global variable). Take every random number from "
        "ctx.sampler.get1D() or get2D() and keep per-sample values in local variables "
        "(handouts/00-setup.md, Random numbers and threads)");
    return outcome;
}

} // namespace pathlab::grader
