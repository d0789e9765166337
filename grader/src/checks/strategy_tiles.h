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
/// and the worst of the judged tiles is judged: with 8 seeds and a bound of 1.5 the reference
/// solution failed 1 grading in 10. Over 200 gradings' seeds at these settings its worst tile
/// was 1.11 (median), 1.34 (90%) and 2.12 (worst); the weights that favour the wrong strategy
/// are 12 to 141 times the better strategy's in their worst tile. Measured by
/// tests/grader/strategy_noise_test.cpp ([.measure]), with the guards' figures below.
inline constexpr double MaxStrategyTileRatio = 3.0;

/// One set of seeds' images, tile by tile, row by row: each tile's per-sample variance
/// (trimmedSampleVariance over its pixels), its mean radiance (over its pixels, channels and the
/// seeds) and that mean's standard error (from the spread of the seeds' tile means).
struct TileFigures {
    std::vector<double> variance, mean, meanError;
    double cpuSeconds = 0; ///< the render's process, as the kernel accounts it
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

/// The worst tile: its index and its variance over the better strategy's, times timeFactor.
struct WorstStrategyTile {
    int index = -1;
    double ratio = 0;
    double timeFactor = 1; ///< strategyTimeFactor, already in `ratio`
};
WorstStrategyTile worstStrategyTile(const StrategyTiles& tiles);

/// A lab may spend more time per sample than the strategies alone do (lab 6 traces both of
/// them; the reference solution took 0.99 of the strategies' time, at most 1.08 over 200
/// gradings), and a variance is worth its time: a lab that took more than
/// StrategyFreeTimeRatio times the strategies' CPU time has its variances counted times the
/// excess (max(1, time ratio / StrategyFreeTimeRatio)). A correct lab's time ratio is near 1, so
/// the verdict does not ride on timings; a lab that draws many samples per sample where it is
/// judged (veach_plates told apart by its command line) pays for them.
inline constexpr double StrategyFreeTimeRatio = 2.0;
double strategyTimeFactor(const StrategyTiles& tiles);

/// The judged tiles' variance summed, the lab's over the better strategy's: at least
/// MinStrategyVarianceShare for images that come from sampling at StrategySpp. MIS is quieter
/// than either strategy where they fail in turn, but not by an order of magnitude over the
/// plates (the reference solution's share was 0.44 to 0.64, least to median, over 200 gradings'
/// seeds); images that barely vary between seeds
/// (a lab that caches each pixel's value and returns it for every seed) are far below.
inline constexpr double MinStrategyVarianceShare = 0.1;
double strategyVarianceShare(const StrategyTiles& tiles);

/// The verdict's words for the worst tile: "tile (3, 4) of veach_plates: variance per sample
/// 0.52, 5.2 times the better strategy's (light alone 0.10, lobe alone 0.95)".
std::string describeStrategyTile(const StrategyTiles& tiles, const WorstStrategyTile& worst);

/// A tile whose mean in the lab's renders differs from what the two strategies alone render
/// there (the plain average of their means), among the tiles the noise check judges (the
/// plates'): a two-sided test at alpha 1e-5 over them (Bonferroni, Student's t with seeds - 1
/// degrees of freedom), and a difference of at least MinMeanDifference of the mean. The noise of
/// an image that does not average to the scene's (a lab that tells veach_plates apart and
/// renders something quiet there) is not compared. The means' standard errors come from 12
/// seeds of heavy-tailed tiles and are themselves rough, hence the floor; a quiet wrong image is
/// off by far more (a black plate: 96% in its tile). The reference solution's false-fail rate
/// over 200 gradings' seeds: none called wrong (tests/grader/strategy_noise_test.cpp,
/// [.measure]).
/// "" when every tile agrees; else its words: "tile (3, 2) of veach_plates averages 0.12 in the
/// lab's renders, where each strategy alone renders 0.31".
inline constexpr double MinMeanDifference = 0.25;
std::string strategyMeanDisagreement(const StrategyTiles& tiles);

} // namespace pathlab::grader
