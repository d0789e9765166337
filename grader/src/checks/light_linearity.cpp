#include "checks/light_linearity.h"

#include "checks/correctness_renders.h"
#include "checks/number_text.h"
#include "checks/run_limits.h"
#include "checks/scene_variants.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace pathlab::grader {

namespace {

/// Relative difference above which two means that a linear lab makes equal are not: far above
/// the rounding of a mean of exactly scaled values (none), far below any clamp's effect.
constexpr double Unequal = 1e-6;

} // namespace

bool scalesWithLight(const std::vector<double>& fullLight, const std::vector<double>& dimmedLight) {
    if (fullLight.size() != dimmedLight.size()) return false;
    for (size_t i = 0; i < fullLight.size(); ++i) {
        const double scaled = dimmedLight[i] / DimmedLight;
        const double size = std::max(std::fabs(fullLight[i]), std::fabs(scaled));
        if (std::fabs(scaled - fullLight[i]) > Unequal * size + 1e-30) return false;
    }
    return true;
}

std::string nonLinearCause(const std::string& scene, const std::vector<double>& fullRatio,
                           const std::vector<double>& dimmedRatio) {
    const auto ratios = [](const std::vector<double>& r) {
        return fixed(r[0], 3) + " " + fixed(r[1], 3) + " " + fixed(r[2], 3);
    };
    return "your lab changes light non-linearly: " + scene +
           " rendered from the same seeds with every light at 1/64 gives observed/expected " +
           ratios(dimmedRatio) + " (red green blue), at full light " + ratios(fullRatio) +
           ", where an estimator gives the same at any strength. A clamp, a cap or a min/max on "
           "the light a path carries (a firefly clamp) is biased: it darkens the image wherever "
           "it cuts, however rarely. Keep every sample as the estimator computes it";
}

LinearityFinding checkLightLinearity(const GraderSetup& setup, Lab lab, const GradingScene& scene,
                                     uint64_t seedBase, const std::vector<double>& fullLight,
                                     const Expectation& expected) {
    LinearityFinding finding;
    const Rubric& r = setup.rubric;
    GradingScene dimmed = scene;
    dimmed.path = writeScaledLightScene(
        scene.path, setup.scratch + "/dimmed_light/" + std::to_string(static_cast<int>(lab)),
        "dimmed", DimmedLight);
    const RenderRequest request = correctnessRequest(setup, dimmed, lab, seedBase, setup.student);
    const RenderResult result = renderLab(request, limitsOf(setup));
    if (!result.ok || result.images.empty()) return finding;
    // The region means over the seeds, as the correctness check takes them.
    std::vector<double> dimmedLight;
    for (const RenderedImage& image : result.images) {
        const std::vector<double> means =
            regionMeans(image.rgb, result.width, result.height, r.tiles);
        if (dimmedLight.empty()) dimmedLight.assign(means.size(), 0.0);
        for (size_t i = 0; i < means.size(); ++i) dimmedLight[i] += means[i];
    }
    for (double& m : dimmedLight) m /= static_cast<double>(result.images.size());
    if (dimmedLight.size() != fullLight.size()) return finding;
    finding.measured = true;
    finding.linear = scalesWithLight(fullLight, dimmedLight);
    if (finding.linear) return finding;
    std::vector<double> full(3), dim(3);
    for (int c = 0; c < 3; ++c) {
        full[static_cast<size_t>(c)] =
            fullLight[static_cast<size_t>(c)] / expected.mean[static_cast<size_t>(c)];
        dim[static_cast<size_t>(c)] = dimmedLight[static_cast<size_t>(c)] / DimmedLight /
                                      expected.mean[static_cast<size_t>(c)];
    }
    finding.cause = nonLinearCause(scene.name, full, dim);
    return finding;
}

} // namespace pathlab::grader
