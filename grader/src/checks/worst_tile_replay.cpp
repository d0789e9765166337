#include "checks/worst_tile_replay.h"

#include "checks/run_limits.h"

#include "pathlab/support/input_error.h"
#include "pathlab/inspect/inspection_json.h"
#include "pathlab/inspect/path_comparison.h"

#include <cmath>

namespace pathlab::grader {

namespace {

/// Enough samples that a path reaching the bug (a bounce at maxDepth, a roulette draw that goes
/// on) is among them in nearly every pixel, few enough that the replay costs a fraction of a
/// second.
constexpr int ReplaySamples = 64;

RenderResult replayThrough(const GraderSetup& setup, const LabRunner& runner, Lab lab,
                           const GradingScene& scene, TilePixel pixel, uint64_t seed) {
    const Rubric& r = setup.rubric;
    const LabParameters parameters =
        scene.parameters.value_or(LabParameters{r.maxDepth, r.continueProb});
    RenderRequest request{&runner,
                          scene.path,
                          requestedIdentity(runner, lab, parameters, seed, r.width, r.height),
                          1,
                          1,
                          setup.threads,
                          setup.scratch};
    request.inspectX = pixel.x;
    request.inspectY = pixel.y;
    request.inspectSamples = ReplaySamples;
    return renderLab(request, limitsOf(setup));
}

} // namespace

TilePixel worstTilePixel(const std::vector<double>& t, int tiles, int width, int height) {
    size_t worst = 3;
    for (size_t i = 3; i < t.size(); ++i)
        if (std::fabs(t[i]) > std::fabs(t[worst])) worst = i;
    const int tile = static_cast<int>(worst / 3) - 1;
    const int column = tile % tiles, row = tile / tiles;
    // The tiles of regionMeans: pixel x is in column x·tiles/width.
    return {(2 * column + 1) * width / (2 * tiles), (2 * row + 1) * height / (2 * tiles)};
}

ReplayFinding replayWorstTile(const GraderSetup& setup, Lab lab, const GradingScene& scene,
                              const std::vector<double>& t, uint64_t seed) {
    if (!PATHLAB_HAS_SOLUTIONS || t.size() < 6) return {};
    const TilePixel pixel =
        worstTilePixel(t, setup.rubric.tiles, setup.rubric.width, setup.rubric.height);
    const RenderResult ours = replayThrough(setup, setup.student, lab, scene, pixel, seed);
    if (!ours.ok) return {};
    const RenderResult theirs = replayThrough(setup, setup.solution, lab, scene, pixel, seed);
    if (!theirs.ok) return {};
    try {
        const PixelInspection yours = readInspectionJson(ours.replayJson, "your lab's replay");
        const PixelInspection reference =
            readInspectionJson(theirs.replayJson, "the reference's replay");
        // The lab's process wrote its file, and may have written another lab, pixel or
        // number of samples than were asked for: such a file says nothing of this lab.
        const auto asked = [&](const PixelInspection& replay) {
            return replay.identity.lab == lab && replay.x == pixel.x && replay.y == pixel.y &&
                   replay.samples.size() == static_cast<size_t>(ReplaySamples);
        };
        if (!asked(yours) || !asked(reference)) return {};
        const PathComparison comparison = comparePaths(yours, reference);
        return {scene.name + ": " + describeComparison(comparison, yours),
                comparison.divergence.has_value()};
    } catch (const InputError&) {
        // The lab's process wrote the file: what it holds is checked, not trusted.
        return {};
    }
}

} // namespace pathlab::grader
