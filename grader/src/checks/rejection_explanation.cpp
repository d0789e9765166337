// The explanations of a correctness check that rejects a lab: per scene, what differs and the
// likely cause its kind of scene can tell; matching means that do not come from paths; scenes
// too noisy to judge.
#include "checks/rejection_explanation.h"

#include "checks/light_linearity.h"
#include "checks/number_text.h"
#include "checks/path_evidence.h"
#include "checks/worst_tile_replay.h"
#include "diagnosis/diagnosis.h"

#include <algorithm>
#include <cmath>

namespace pathlab::grader {

/// Whether any region (of a scene, or of all scenes) differs from its reference.
bool anyRejected(const std::vector<bool>& rejected) {
    return std::any_of(rejected.begin(), rejected.end(), [](bool b) { return b; });
}

/// The name a diagnosis goes by: the cause up to the explanation after the colon.
std::string causeName(const std::string& cause) { return cause.substr(0, cause.find(':')); }

namespace {

/// A likely cause in the details; the first one told names the diagnosis.
void tellLikelyCause(const std::string& cause, Attempt& attempt) {
    attempt.details.push_back("likely cause: " + cause);
    if (attempt.diagnosis.empty()) attempt.diagnosis = causeName(cause);
}

/// Holm's rejections over all scenes' regions in a row, cut back into each scene's regions.
std::vector<std::vector<bool>> rejectionsByScene(const std::vector<Comparison>& scenes,
                                                 const std::vector<bool>& rejected) {
    std::vector<std::vector<bool>> byScene;
    size_t offset = 0;
    for (const Comparison& c : scenes) {
        byScene.emplace_back(rejected.begin() + offset, rejected.begin() + offset + c.p.size());
        offset += c.p.size();
    }
    return byScene;
}

/// Which kinds of scene reject the lab: they decide which likely causes it may be told.
struct RejectingScenes {
    bool furnace = false, refraction = false, publicScene = false;
};

/// The furnaces have no glass: a lab that one of them rejects has a fault elsewhere, which the
/// refraction check's image shows too, so only a lab that every furnace accepts is told about
/// refraction; and only one that the refraction check accepts too about its diffuse directions
/// (mixed_surfaces holds glass as well).
RejectingScenes rejectingScenes(const std::vector<GradingScene>& scenes,
                                const std::vector<bool>& sceneRejected) {
    RejectingScenes rejecting;
    for (size_t s = 0; s < scenes.size(); ++s) {
        rejecting.furnace = rejecting.furnace || (scenes[s].furnace && sceneRejected[s]);
        rejecting.refraction =
            rejecting.refraction ||
            (!scenes[s].hidden && scenes[s].reference.scene == "refraction_check" &&
             sceneRejected[s]);
        rejecting.publicScene = rejecting.publicScene || (!scenes[s].hidden && sceneRejected[s]);
    }
    return rejecting;
}

/// The whole image's mean over its three channels: a furnace's one value.
double wholeImageMean(const Comparison& c) {
    return (c.observed[0].mean + c.observed[1].mean + c.observed[2].mean) / 3;
}

/// The whole image's observed/expected per channel, each with its confidence interval.
struct ChannelRatios {
    std::string text; ///< " red R [LOW, HIGH] green ..."
    std::vector<ChannelInterval> intervals;
};

ChannelRatios channelRatios(const Comparison& c, const Expectation& e, const Rubric& r) {
    const double critical = studentCritical(r.alpha, r.seeds - 1);
    const char* channel[3] = {"red", "green", "blue"};
    ChannelRatios ratios;
    for (int ch = 0; ch < 3; ++ch) {
        const double ratio = c.observed[ch].mean / e.mean[ch];
        const double half =
            critical * std::hypot(c.observed[ch].standardError, e.standardError[ch]) / e.mean[ch];
        ratios.text += std::string(" ") + channel[ch] + " " + fixed(ratio, 3) + " [" +
                       fixed(ratio - half, 3) + ", " + fixed(ratio + half, 3) + "]";
        ratios.intervals.push_back({ratio - half, ratio + half});
    }
    return ratios;
}

/// "N of M tiles differ ...: (column,row) ..." for a scene's regions (the whole image's three
/// channels, then each tile's), or "" when no tile differs.
std::string differingTiles(const std::vector<bool>& regionsRejected, int tilesPerSide) {
    std::string tiles;
    int tileCount = 0;
    for (size_t i = 3; i < regionsRejected.size(); i += 3) {
        bool any = false;
        for (int ch = 0; ch < 3; ++ch) any = any || regionsRejected[i + ch];
        if (!any) continue;
        const int tile = static_cast<int>(i / 3) - 1;
        ++tileCount;
        tiles += " (" + std::to_string(tile % tilesPerSide) + "," +
                 std::to_string(tile / tilesPerSide) + ")";
    }
    if (tileCount == 0) return "";
    return std::to_string(tileCount) + " of " + std::to_string(tilesPerSide * tilesPerSide) +
           " tiles differ (column,row from the top left):" + tiles;
}

/// Channels off in opposite ways point to the pick's probabilities, channels off alike to the
/// diffuse directions (channelsOffOppositeWays). Lab 1 picks nothing: it is told only what
/// differs.
void explainMixedSurfaces(Lab lab, const GradingScene& scene,
                          const std::vector<ChannelInterval>& intervals, Attempt& attempt) {
    const bool opposite = channelsOffOppositeWays(intervals);
    const std::string cause = opposite ? likelyPickDivideCause(lab) : likelyDirectionCause(lab);
    if (!cause.empty())
        tellLikelyCause(cause, attempt);
    else if (opposite)
        attempt.details.push_back(scene.name +
                                  ": some colour channels are too bright and others too dark");
}

/// A public scene that differs, in the details: its channels' ratios, the tiles that differ, and
/// the likely cause that its kind of scene can tell (unless `tellCauses` is false: a lab that is
/// not linear in light, whose values no model of a linear lab's bug explains).
void explainScene(const GraderSetup& setup, Lab lab, const GradingScene& scene, const Comparison& c,
                  const std::vector<bool>& regionsRejected, const RejectingScenes& rejecting,
                  bool tellCauses, Attempt& attempt) {
    const ChannelRatios ratios = channelRatios(c, scene.reference.forLab(lab), setup.rubric);
    attempt.details.push_back(scene.name + ": observed/expected" + ratios.text);
    if (const std::string tiles = differingTiles(regionsRejected, setup.rubric.tiles);
        !tiles.empty())
        attempt.details.push_back(scene.name + ": " + tiles);
    if (tellCauses && scene.reference.scene == "mixed_surfaces" && !rejecting.furnace &&
        !rejecting.refraction)
        explainMixedSurfaces(lab, scene, ratios.intervals, attempt);
    if (tellCauses && scene.reference.scene == "refraction_check" && !rejecting.furnace)
        tellLikelyCause(likelyRefractionCause(lab), attempt);
    if (scene.furnace)
        attempt.details.push_back(scene.name + ": " + fixed(wholeImageMean(c), 4) +
                                  ", where a correct lab gives " +
                                  fixed(correctFurnaceValue(lab, *scene.furnace), 4));
}

/// The public scene a lab's linearity in light is checked on (light_linearity.h): a furnace that
/// rejects it, else the first public scene that does; none when only hidden scenes do.
const GradingScene* linearityScene(const std::vector<GradingScene>& scenes,
                                   const std::vector<bool>& sceneRejected) {
    const GradingScene* chosen = nullptr;
    for (size_t s = 0; s < scenes.size(); ++s) {
        if (scenes[s].hidden || !sceneRejected[s]) continue;
        if (scenes[s].furnace) return &scenes[s];
        if (!chosen) chosen = &scenes[s];
    }
    return chosen;
}

} // namespace

/// Explains a rejection in `attempt`'s details and diagnosis: per scene, the whole image's
/// observed/expected per channel with a confidence interval, the tiles that differ, and a likely
/// cause where the furnace can tell.
void explainRejection(const GraderSetup& setup, Lab lab, const SceneComparisons& found,
                      const std::vector<bool>& rejected, uint64_t seed, Attempt& attempt) {
    const std::vector<std::vector<bool>> regionsRejected =
        rejectionsByScene(found.scenes, rejected);
    std::vector<bool> sceneRejected;
    for (const std::vector<bool>& regions : regionsRejected)
        sceneRejected.push_back(anyRejected(regions));
    const RejectingScenes rejecting = rejectingScenes(setup.scenes, sceneRejected);
    // A lab that is not linear in light is told that first, and nothing the models of linear
    // labs' bugs would make of its values.
    bool linear = true;
    if (const GradingScene* probed = linearityScene(setup.scenes, sceneRejected)) {
        const size_t s = static_cast<size_t>(probed - setup.scenes.data());
        std::vector<double> fullLight;
        for (const MeanEstimate& m : found.scenes[s].observed) fullLight.push_back(m.mean);
        const LinearityFinding finding = checkLightLinearity(setup, lab, *probed, seed, fullLight,
                                                             probed->reference.forLab(lab));
        if (finding.measured && !finding.linear) {
            linear = false;
            attempt.details.push_back("likely cause: " + finding.cause);
            attempt.diagnosis = causeName(finding.cause);
        }
    }
    // Every furnace's value, accepted or not, narrows down the known bugs that explain them.
    std::vector<FurnaceObservation> furnaces;
    for (size_t s = 0; s < setup.scenes.size(); ++s) {
        const GradingScene& scene = setup.scenes[s];
        const Comparison& c = found.scenes[s];
        if (scene.furnace)
            furnaces.push_back({*scene.furnace, wholeImageMean(c), c.observed[0].standardError});
        if (scene.hidden)
            attempt.hiddenDetails.push_back(
                scene.name + (sceneRejected[s] ? HiddenSceneDiffers : HiddenSceneMatches));
        else if (sceneRejected[s])
            explainScene(setup, lab, scene, c, regionsRejected[s], rejecting, linear, attempt);
    }
    if (!rejecting.publicScene)
        attempt.hiddenDetails.push_back(
            "every scene you can see matches: what differs is something only a hidden scene has "
            "(a material, a light or a path the public scenes lack)");
    if (rejecting.furnace && linear) {
        const std::vector<std::string> causes = likelyFurnaceCauses(lab, furnaces, found.stepsOpen);
        if (!causes.empty()) {
            attempt.details.push_back("likely cause: " + causes.front());
            // The furnaces' diagnosis is the most specific: it wins over any told before.
            attempt.diagnosis = causeName(causes.front());
        } else {
            attempt.details.push_back("no bug the grader knows gives these furnace values");
        }
    }
    // A pixel of each public scene that differs, replayed beside the reference until one's paths
    // part: where they part names a step the furnaces' numbers cannot (worst_tile_replay.h).
    ReplayFinding agreed;
    for (size_t s = 0; s < setup.scenes.size(); ++s) {
        if (setup.scenes[s].hidden || !sceneRejected[s]) continue;
        const ReplayFinding replay =
            replayWorstTile(setup, lab, setup.scenes[s], found.scenes[s].t, seed);
        if (replay.diverged) {
            attempt.details.push_back("replay: " + replay.text);
            return;
        }
        if (agreed.text.empty()) agreed = replay;
    }
    if (!agreed.text.empty())
        attempt.details.push_back("replay: " + agreed.text +
                                  " (what differs lies on paths these samples did not take)");
}

/// Whether the regions of any public scene were rejected.
bool publicSceneRejected(const GraderSetup& setup, const SceneComparisons& found,
                         const std::vector<bool>& rejected) {
    const std::vector<std::vector<bool>> byScene = rejectionsByScene(found.scenes, rejected);
    for (size_t s = 0; s < setup.scenes.size(); ++s)
        if (!setup.scenes[s].hidden && anyRejected(byScene[s])) return true;
    return false;
}

/// Means that match from images that do not come from paths (path_evidence.h): says which
/// scenes in `attempt` and returns true; false where every scene's images are traced.
bool explainUntraced(const GraderSetup& setup, const SceneComparisons& found, Attempt& attempt) {
    bool untraced = false;
    for (size_t s = 0; s < setup.scenes.size(); ++s) {
        if (found.untraced[s].empty()) continue;
        untraced = true;
        const GradingScene& scene = setup.scenes[s];
        if (scene.hidden)
            attempt.hiddenDetails.push_back(scene.name + ": " + NotTracedDiagnosis);
        else
            attempt.details.push_back(scene.name + ": the means match, but " + found.untraced[s]);
    }
    if (untraced) attempt.diagnosis = NotTracedDiagnosis;
    return untraced;
}

namespace {

/// A share as a whole percentage ("140%"), or with two figures below 10% ("0.66%").
std::string percent(double share) {
    return (100 * share >= 10 ? std::to_string(std::lround(100 * share))
                              : significant(100 * share, 2)) +
           "%";
}

} // namespace

/// Scenes whose renders spread from seed to seed too much to be judged (seed_spread.h): says
/// which in `attempt` and returns true; false where every scene could be judged.
bool explainTooNoisy(const GraderSetup& setup, const SceneComparisons& found, Attempt& attempt) {
    bool tooNoisy = false;
    for (size_t s = 0; s < setup.scenes.size(); ++s) {
        const SeedSpread& spread = found.spreads[s];
        if (!tooNoisyToJudge(spread)) continue;
        tooNoisy = true;
        const std::string why =
            spread.relativeStandardError > MaxRelativeStandardError
                ? "the mean of your image changes from seed to seed by " +
                      percent(spread.relativeStandardError) +
                      " of itself (its standard error over the seeds; a correct lab's is under "
                      "1%)"
                : "your image's mean changes from seed to seed " +
                      significant(
                          std::max(spread.wholeImageCorrelation, spread.medianTileCorrelation), 2) +
                      " times as much as its pixels' own noise allows (a path tracer's pixels "
                      "are independent: about 1)";
        const std::string text =
            why +
            ": a comparison with the reference cannot tell whether the mean is right, so "
            "it is not taken as matching; likely cause: " +
            TooNoisyCause;
        if (setup.scenes[s].hidden)
            attempt.hiddenDetails.push_back(setup.scenes[s].name + ": " + text);
        else
            attempt.details.push_back(setup.scenes[s].name + ": " + text);
    }
    if (tooNoisy) attempt.diagnosis = causeName(TooNoisyCause);
    return tooNoisy;
}

} // namespace pathlab::grader
