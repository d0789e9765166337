#include "checks/strategy_noise.h"

#include "checks/grading_scenes.h"
#include "checks/run_limits.h"
namespace pathlab::grader {

namespace {

/// `runner`'s renders of the scene with `strategies`; empty with `failure` set when they fail.
TileFigures renderTiles(const GraderSetup& setup, const LabRunner& runner, Lab lab,
                        StrategyChoice strategies, uint64_t seed, std::string& failure) {
    LabParameters parameters{setup.rubric.maxDepth, setup.rubric.continueProb};
    parameters.strategies = strategies;
    const RenderRequest request{
        &runner,
        publicScenePath(StrategyScene),
        requestedIdentity(runner, lab, parameters, seed, StrategyWidth, StrategyHeight),
        StrategySpp,
        StrategySeeds,
        setup.threads,
        setup.scratch};
    const RenderResult result = renderLab(request, renderLimits(setup.rubric));
    if (!result.ok) {
        failure = result.failure;
        return {};
    }
    std::vector<std::vector<float>> images;
    for (const RenderedImage& rendered : result.images) images.push_back(rendered.rgb);
    TileFigures figures = tileFigures(images);
    figures.cpuSeconds = result.process.cpuSeconds;
    return figures;
}

} // namespace

bool combinesStrategies(Lab lab) { return lab == Lab::Mis; }

StrategyTiles measureStrategyTiles(const GraderSetup& setup, Lab lab) {
    StrategyTiles tiles;
    tiles.columns = StrategyWidth / StrategyTileSize;
    tiles.rows = StrategyHeight / StrategyTileSize;
    // Seeds of their own, apart from the correctness renders' and from one another's.
    const uint64_t seed = setup.seedBase * 1000 + 500;
    std::string failure;
    tiles.lab = renderTiles(setup, setup.student, lab, StrategyChoice::Both, seed, failure);
    if (!failure.empty()) {
        tiles.failure =
            "the lab's renders of " + std::string(StrategyScene) + " failed: " + failure;
        return tiles;
    }
    // The strategies alone are the reference solution's; a student's release has none, and
    // takes the lab's own, which it renders through ctx.strategyWeight (as make strategies).
    tiles.strategiesByLab = !setup.solutionsAvailable;
    const LabRunner& strategies = tiles.strategiesByLab ? setup.student : setup.solution;
    tiles.light = renderTiles(setup, strategies, lab, StrategyChoice::LightOnly,
                              seed + StrategySeeds, failure);
    if (failure.empty())
        tiles.lobe = renderTiles(setup, strategies, lab, StrategyChoice::LobeOnly,
                                 seed + 2 * StrategySeeds, failure);
    if (!failure.empty())
        tiles.failure =
            std::string(tiles.strategiesByLab ? "the lab's" : "the reference solution's") +
            " renders of " + StrategyScene + " with one strategy alone failed: " + failure;
    return tiles;
}

} // namespace pathlab::grader
