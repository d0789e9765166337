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
    return {{"variance", f.variance}, {"mean", f.mean}, {"mean_error", f.meanError}};
}

TileFigures readFigures(const nlohmann::json& j, size_t count) {
    TileFigures f{j.at("variance").get<std::vector<double>>(),
                  j.at("mean").get<std::vector<double>>(),
                  j.at("mean_error").get<std::vector<double>>()};
    for (const auto* v : {&f.variance, &f.mean, &f.meanError})
        if (!v->empty() && v->size() != count)
            throw InputError("noise.strategies: " + std::to_string(v->size()) +
                             " tiles where columns x rows is " + std::to_string(count));
    return f;
}

/// The tiles of the plates' rows, which the noise check judges.
std::vector<size_t> judgedTiles(int columns) {
    std::vector<size_t> judged;
    for (int row = StrategyFirstRow; row < StrategyFirstRow + StrategyJudgedRows; ++row)
        for (int column = 0; column < columns; ++column)
            judged.push_back(static_cast<size_t>(row * columns + column));
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
    const std::vector<size_t> judged = judgedTiles(tiles.columns);
    double betterSum = 0;
    for (const size_t i : judged)
        betterSum += std::min(tiles.light.variance[i], tiles.lobe.variance[i]);
    const double negligible = StrategyNegligibleShare * betterSum / double(judged.size());
    WorstStrategyTile worst;
    for (const size_t i : judged) {
        const double better = std::min(tiles.light.variance[i], tiles.lobe.variance[i]);
        if (better <= negligible) continue;
        const double ratio = tiles.lab.variance[i] / better;
        if (worst.index < 0 || ratio > worst.ratio) worst = {static_cast<int>(i), ratio};
    }
    return worst;
}

std::string describeStrategyTile(const StrategyTiles& tiles, const WorstStrategyTile& worst) {
    if (worst.index < 0 || tiles.columns == 0) return "";
    const size_t i = static_cast<size_t>(worst.index);
    return "tile (" + std::to_string(worst.index % tiles.columns) + ", " +
           std::to_string(worst.index / tiles.columns) + ") of " + StrategyScene +
           ": variance per sample " + significant(tiles.lab.variance[i], 3) + ", " +
           significant(worst.ratio, 3) + " times the better strategy's (light alone " +
           significant(tiles.light.variance[i], 3) + ", lobe alone " +
           significant(tiles.lobe.variance[i], 3) + ")";
}

std::string strategyMeanDisagreement(const StrategyTiles& tiles) {
    if (!complete(tiles)) return "";
    const std::vector<size_t> judged = judgedTiles(tiles.columns);
    const double critical =
        studentCritical(1e-5 / static_cast<double>(judged.size()), StrategySeeds - 1);
    for (const size_t i : judged) {
        // The two strategies' means pooled by their standard errors: each is unbiased, and the
        // better one for the tile has the smaller error.
        const double a = tiles.light.meanError[i], b = tiles.lobe.meanError[i];
        double expected = 0, error = 0;
        if (a > 0 && b > 0) {
            const double wa = 1 / (a * a), wb = 1 / (b * b);
            expected = (wa * tiles.light.mean[i] + wb * tiles.lobe.mean[i]) / (wa + wb);
            error = std::sqrt(1 / (wa + wb));
        } else {
            expected = a > 0 ? tiles.lobe.mean[i] : tiles.light.mean[i];
        }
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
