#pragma once
/// Lab 6's noise check's figures: veach_plates' per-sample variance tile by tile, the lab's and
/// each strategy's alone, and the worst tile against the better strategy (strategy_noise.h
/// measures them). Kept in measurements.json, so a re-score judges them again.

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace pathlab::grader {

/// The scene, its size and tiles, and how much is rendered: 12 seeds of 16 spp at 128×96 take
/// about a second per strategy on 2 cores.
inline constexpr const char* StrategyScene = "veach_plates";
inline constexpr int StrategyWidth = 128, StrategyHeight = 96, StrategyTileSize = 16;
inline constexpr int StrategySpp = 16, StrategySeeds = 12;
/// The tile rows judged: the plates' band (rows 2 to 4 of 6). The lights above them are seen
/// straight from the camera, and their bright edges' noise, the camera's jitter across them, is
/// the same for every strategy but so heavy-tailed that 8 seeds measure it only to a factor of 2.
inline constexpr int StrategyFirstRow = 2, StrategyJudgedRows = 3;
/// Tiles whose better strategy's variance is below this share of the judged tiles' mean are
/// left out: the dark floor in front of the plates, which no strategy makes noisy, and whose
/// variances are too small for a ratio to mean anything.
inline constexpr double StrategyNegligibleShare = 0.01;

/// A tile's verdict needs its variance at most this many times the better strategy's. Each
/// tile's variance is itself an estimate from 12 seeds, heavy-tailed where a strategy is poor,
/// and the worst of 24 tiles is judged: with 8 seeds and a bound of 1.5 the reference solution
/// failed 1 grading in 10. The weights that favour the wrong strategy are 18 and 27 times the
/// better strategy's in their worst tile; the solution's worst tile, over 200 gradings' seeds,
/// is in tests/grader/strategy_noise_test.cpp ([.measure]).
inline constexpr double MaxStrategyTileRatio = 3.0;

/// One set of seeds' images, tile by tile, row by row: each tile's per-sample variance
/// (trimmedSampleVariance over its pixels), its mean radiance (over its pixels, channels and the
/// seeds) and that mean's standard error (from the spread of the seeds' tile means).
struct TileFigures {
    std::vector<double> variance, mean, meanError;
};

/// The lab's tiles and each strategy's alone.
struct StrategyTiles {
    TileFigures lab, light, lobe;
    int columns = 0, rows = 0;
    /// The strategies alone were the lab's own (a build without the reference solutions).
    bool strategiesByLab = false;
    std::string failure; ///< why not measured ("" when measured)
};

/// The tiles of `images`: StrategySeeds renders of StrategyWidth × StrategyHeight at
/// StrategySpp.
TileFigures tileFigures(const std::vector<std::vector<float>>& images);

nlohmann::json strategyTilesJson(const StrategyTiles& tiles);
/// Throws InputError on a malformed entry.
StrategyTiles readStrategyTiles(const nlohmann::json& j);

/// The worst tile: its index and its variance over the better strategy's.
struct WorstStrategyTile {
    int index = -1;
    double ratio = 0;
};
WorstStrategyTile worstStrategyTile(const StrategyTiles& tiles);

/// The verdict's words for the worst tile: "tile (3, 4) of veach_plates: variance per sample
/// 0.52, 5.2 times the better strategy's (light alone 0.10, lobe alone 0.95)".
std::string describeStrategyTile(const StrategyTiles& tiles, const WorstStrategyTile& worst);

/// A tile whose mean in the lab's renders differs from what the two strategies alone render
/// there (their means pooled by their standard errors), among the judged tiles (the plates'): a
/// two-sided test at alpha 1e-5 over them (Bonferroni, Student's t with seeds - 1 degrees of
/// freedom), and a difference of at least MinMeanDifference of the mean. The noise of an image that
/// does not average to the scene's (a lab that tells veach_plates apart and renders something quiet
/// there) is not compared. The means' standard errors come from 12 seeds of heavy-tailed tiles and
/// are themselves rough: at a 5% floor, 2 of the reference solution's 200 measured gradings were
/// called wrong; a quiet wrong image is off by far more (a black plate: 96% in its tile).
/// "" when every tile agrees; else its words: "tile (3, 2) of veach_plates averages 0.12 in the
/// lab's renders, where each strategy alone renders 0.31".
inline constexpr double MinMeanDifference = 0.25;
std::string strategyMeanDisagreement(const StrategyTiles& tiles);

} // namespace pathlab::grader
