#include "checks/strategy_tiles.h"

#include "checks/number_text.h"
#include "checks/hypothesis_tests.h"
#include "checks/seed_variance.h"

#include "pathlab/support/input_error.h"

#include <algorithm>
#include <cmath>

namespace pathlab::grader {

namespace {

/// One seed's image cut to the tile at (column, row).
std::vector<float> tileOf(const std::vector<float>& image, int column, int row) {
    std::vector<float> tile;
    tile.reserve(3 * StrategyTileSize * StrategyTileSize);
    for (int y = row * StrategyTileSize; y < (row + 1) * StrategyTileSize; ++y) {
        const auto first = image.begin() + 3 * (static_cast<std::ptrdiff_t>(y) * StrategyWidth +
                                                column * StrategyTileSize);
        tile.insert(tile.end(), first, first + 3 * StrategyTileSize);
    }
    return tile;
}

} // namespace

TileFigures tileFigures(const std::vector<std::vector<float>>& images) {
    TileFigures figures;
    const double seeds = static_cast<double>(images.size());
    for (int row = 0; row < StrategyHeight / StrategyTileSize; ++row)
        for (int column = 0; column < StrategyWidth / StrategyTileSize; ++column) {
            std::vector<std::vector<float>> tiles;
            std::vector<double> means;
            for (const std::vector<float>& image : images) {
                tiles.push_back(tileOf(image, column, row));
                double sum = 0;
                for (const float v : tiles.back()) sum += v;
                means.push_back(sum / static_cast<double>(tiles.back().size()));
            }
            figures.variance.push_back(trimmedSampleVariance(tiles, StrategySpp));
            double mean = 0, squares = 0;
            for (const double m : means) mean += m / seeds;
            for (const double m : means) squares += (m - mean) * (m - mean);
            figures.mean.push_back(mean);
            figures.meanError.push_back(seeds > 1 ? std::sqrt(squares / (seeds - 1) / seeds) : 0);
        }
    return figures;
}

namespace {

nlohmann::json figuresJson(const TileFigures& f) {
    return {{"variance", f.variance},
            {"mean", f.mean},
            {"mean_error", f.meanError},
            {"cpu_seconds", f.cpuSeconds}};
}

TileFigures readFigures(const nlohmann::json& j, size_t count) {
    TileFigures f{j.at("variance").get<std::vector<double>>(),
                  j.at("mean").get<std::vector<double>>(),
                  j.at("mean_error").get<std::vector<double>>(), j.value("cpu_seconds", 0.0)};
    for (const auto* v : {&f.variance, &f.mean, &f.meanError})
        if (!v->empty() && v->size() != count)
            throw InputError("noise.strategies: " + std::to_string(v->size()) +
                             " tiles where columns x rows is " + std::to_string(count));
    return f;
}

/// The tiles the noise check judges: those of the plates' rows, but the ones whose better
/// strategy's variance is negligible (StrategyNegligibleShare of their mean): the dark ends
/// beside the plates, which no strategy makes noisy. `tiles` must be complete().
std::vector<size_t> judgedTiles(const StrategyTiles& tiles) {
    std::vector<size_t> plates;
    double betterSum = 0;
    for (int row = StrategyFirstRow; row < StrategyFirstRow + StrategyJudgedRows; ++row)
        for (int column = 0; column < tiles.columns; ++column) {
            const size_t i = static_cast<size_t>(row * tiles.columns + column);
            plates.push_back(i);
            betterSum += std::min(tiles.light.variance[i], tiles.lobe.variance[i]);
        }
    const double negligible = StrategyNegligibleShare * betterSum / double(plates.size());
    std::vector<size_t> judged;
    for (const size_t i : plates)
        if (std::min(tiles.light.variance[i], tiles.lobe.variance[i]) > negligible)
            judged.push_back(i);
    return judged;
}

/// Whether the tile figures of all three are there, one per tile.
bool complete(const StrategyTiles& tiles) {
    const size_t count = static_cast<size_t>(tiles.columns * tiles.rows);
    for (const TileFigures* f : {&tiles.lab, &tiles.light, &tiles.lobe})
        if (f->variance.size() != count || f->mean.size() != count || f->meanError.size() != count)
            return false;
    return count > 0;
}

} // namespace

nlohmann::json strategyTilesJson(const StrategyTiles& tiles) {
    return {{"lab", figuresJson(tiles.lab)},
            {"light", figuresJson(tiles.light)},
            {"lobe", figuresJson(tiles.lobe)},
            {"columns", tiles.columns},
            {"rows", tiles.rows},
            {"strategies_by_lab", tiles.strategiesByLab},
            {"failure", tiles.failure}};
}

StrategyTiles readStrategyTiles(const nlohmann::json& j) {
    StrategyTiles tiles;
    tiles.columns = j.at("columns");
    tiles.rows = j.at("rows");
    tiles.failure = j.at("failure");
    tiles.strategiesByLab = j.value("strategies_by_lab", false);
    const size_t count = static_cast<size_t>(std::max(0, tiles.columns * tiles.rows));
    tiles.lab = readFigures(j.at("lab"), count);
    tiles.light = readFigures(j.at("light"), count);
    tiles.lobe = readFigures(j.at("lobe"), count);
    return tiles;
}

WorstStrategyTile worstStrategyTile(const StrategyTiles& tiles) {
    if (!complete(tiles)) return {};
    WorstStrategyTile worst;
    const double factor = strategyTimeFactor(tiles);
    for (const size_t i : judgedTiles(tiles)) {
        const double better = std::min(tiles.light.variance[i], tiles.lobe.variance[i]);
        const double ratio = tiles.lab.variance[i] / better * factor;
        if (worst.index < 0 || ratio > worst.ratio) worst = {static_cast<int>(i), ratio, factor};
    }
    return worst;
}

double strategyTimeFactor(const StrategyTiles& tiles) {
    const double strategies = (tiles.light.cpuSeconds + tiles.lobe.cpuSeconds) / 2;
    if (!(strategies > 0) || !(tiles.lab.cpuSeconds > 0)) return 1;
    return std::max(1.0, tiles.lab.cpuSeconds / strategies / StrategyFreeTimeRatio);
}

double strategyVarianceShare(const StrategyTiles& tiles) {
    if (!complete(tiles)) return 0;
    double lab = 0, better = 0;
    for (const size_t i : judgedTiles(tiles)) {
        lab += tiles.lab.variance[i];
        better += std::min(tiles.light.variance[i], tiles.lobe.variance[i]);
    }
    return better > 0 ? lab / better : 1;
}

std::string describeStrategyTile(const StrategyTiles& tiles, const WorstStrategyTile& worst) {
    if (worst.index < 0 || tiles.columns == 0) return "";
    const size_t i = static_cast<size_t>(worst.index);
    return "tile (" + std::to_string(worst.index % tiles.columns) + ", " +
           std::to_string(worst.index / tiles.columns) + ") of " + StrategyScene +
           ": variance per sample " + significant(tiles.lab.variance[i], 3) + ", " +
           significant(worst.ratio, 3) + " times the better strategy's" +
           (worst.timeFactor > 1
                ? " (counted " + significant(worst.timeFactor, 3) + " times for the lab's CPU time)"
                : std::string()) +
           " (light alone " + significant(tiles.light.variance[i], 3) + ", lobe alone " +
           significant(tiles.lobe.variance[i], 3) + ")";
}

std::string strategyMeanDisagreement(const StrategyTiles& tiles) {
    if (!complete(tiles)) return "";
    const std::vector<size_t> judged = judgedTiles(tiles);
    if (judged.empty()) return "";
    const double critical =
        studentCritical(1e-5 / static_cast<double>(judged.size()), StrategySeeds - 1);
    for (const size_t i : judged) {
        // The two strategies' plain average: each is unbiased, and so is it. (Pooled by their
        // estimated standard errors it would not be: a heavy-tailed tile's low mean comes with a
        // low error, and the pooled figure leant low, 28% on a dark tile in 8 gradings of 200.)
        const double expected = (tiles.light.mean[i] + tiles.lobe.mean[i]) / 2;
        const double error = std::hypot(tiles.light.meanError[i], tiles.lobe.meanError[i]) / 2;
        const double difference = tiles.lab.mean[i] - expected;
        const double se = std::hypot(error, tiles.lab.meanError[i]);
        if (std::fabs(difference) <= critical * se) continue;
        if (std::fabs(difference) <= MinMeanDifference * std::fabs(expected) + 1e-6) continue;
        return "tile (" + std::to_string(i % static_cast<size_t>(tiles.columns)) + ", " +
               std::to_string(i / static_cast<size_t>(tiles.columns)) + ") of " + StrategyScene +
               " averages " + significant(tiles.lab.mean[i], 3) +
               " in the lab's renders, where each strategy alone renders " +
               significant(expected, 3);
    }
    return "";
}

} // namespace pathlab::grader
