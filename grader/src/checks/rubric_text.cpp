#include "checks/rubric_text.h"

#include "checks/glossy_furnace_scene.h"
#include "diagnosis/diagnosis.h"
#include "checks/run_limits.h"
#include "checks/speed_check.h"
#include "checks/strategy_tiles.h"
#include "common/local_time.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace pathlab::grader {

namespace {

/// "branching 8, uniform 32, importance 16, roulette 32": one of LabRubric's counts by lab.
std::string perLab(const Rubric& r, int LabRubric::*count) {
    std::string text;
    for (Lab lab : AllLabs)
        text += (text.empty() ? "" : ", ") + std::string(labName(lab)) + " " +
                std::to_string(r.forLab(lab).*count);
    return text;
}

} // namespace

std::string releasedRubricNote(const Rubric& r, const std::string& rubricPath) {
    const std::filesystem::path release =
        std::filesystem::path(rubricPath).parent_path() / "release.json";
    std::ifstream in(release);
    const nlohmann::json j = in ? nlohmann::json::parse(in, nullptr, false) : nlohmann::json();
    if (!j.is_object() || !j.contains("rubric_hash")) return "";
    const std::string hash = j.value("rubric_hash", "");
    std::string note = "this release carries the instructor's rubric " + j.value("rubric", "?") +
                       " (hash " + hash + "), packaged " + j.value("packaged_at", "?") + "\n";
    if (hash != r.hash)
        note += "note: " + rubricPath + " is not that rubric (hash " + r.hash +
                "): it was edited since, or another was given, and a grade under it may differ "
                "from your instructor's\n";
    return note;
}

std::string rubricText(const Rubric& r, const std::string& rubricPath, int hiddenScenes) {
    std::ostringstream out;
    out << "PathLab rubric: " << rubricPath << " (hash " << r.hash << ")\n"
        << releasedRubricNote(r, rubricPath) << "\npoints\n";
    double total = 0;
    for (Lab lab : AllLabs) {
        const LabPoints& p = r.forLab(lab).points;
        const double labTotal = p.correctness + p.noise + p.speed;
        total += labTotal;
        out << "  " << labName(lab) << std::string(12 - labName(lab).size(), ' ') << "correctness "
            << p.correctness << " + noise " << p.noise << " + speed " << p.speed << " = "
            << labTotal << "\n";
    }
    out << "  total " << total << "; noise and speed count only for a correct lab\n\n";

    out << "correctness: the mean radiance of " << r.seeds << " independent renders (seeds) of "
        << r.width << "x" << r.height << " pixels,\n  over the whole image and each of its "
        << r.tiles << "x" << r.tiles
        << " tiles, agrees with the reference's (t-tests: a correct lab\n  fails "
           "with probability at most "
        << r.alpha
        << ", and a failure counts only if fresh seeds fail "
           "again)\n"
        << "  samples per pixel: " << perLab(r, &LabRubric::correctnessSpp) << "\n"
        << "  labs 1-3 at maxDepth " << r.maxDepth << "; lab 4 at continueProb " << r.continueProb
        << "\n"
        << "  public scenes (models/):";
    for (const std::string& scene : r.scenes) out << " " << scene;
    out << "\n  parameter check: " << r.parameterCheck.scene << " again, labs 1-3 at maxDepth "
        << r.parameterCheck.maxDepth << " and lab 4 at continueProb "
        << r.parameterCheck.continueProb << ",\n  against its exact value by the same test\n";
    out << "  the labs that write a glossy lobe (labs 5 and 6) also: " << GlossyFurnaceScenes[0]
        << " and " << GlossyFurnaceScenes[1]
        << " (analytic; the tilted one a variant of\n  its own for each submission), and the lobe "
           "check of sampleLobe and lobePdf\n";
    if (hiddenScenes > 0)
        out << "  hidden scenes: " << hiddenScenes
            << " (feedback says pass or fail; Gradescope shows that " << r.hiddenScenesVisibility
            << ")\n";
    else if (r.sceneVariants > 0 &&
             std::any_of(r.scenes.begin(), r.scenes.end(), [&](const std::string& scene) {
                 return !furnaceModel(scene, r.maxDepth, r.continueProb);
             }))
        out << "  hidden scenes: none here; an instructor's batch without hidden scenes grades on "
            << r.sceneVariants
            << " variant(s) of the public scenes\n  (hidden_scenes.variants: the same geometry, "
               "other colours and light)\n";
    else
        out << "  hidden scenes: none here (your instructor's grader may add some)\n";
    if (r.variants.perStudent) {
        const VariantSettings& v = r.variants;
        out << "  each student's own scenes too (variants): a furnace of albedo in ["
            << v.albedo.low << ", " << v.albedo.high << "], Le in [" << v.emission.low << ", "
            << v.emission.high << "], maxDepth in [" << v.maxDepth.low << ", " << v.maxDepth.high
            << "] (analytic)";
        if (!v.boxScene.empty())
            out << ",\n  and " << v.boxScene << " with each Kd times [" << v.reflectance.low << ", "
                << v.reflectance.high << "] and each Ke times [" << v.light.low << ", "
                << v.light.high << "]";
        out << "; make grade VARIANT=DIR grades on yours\n";
    }

    out << "\nnoise: the per-sample variance on " << r.noiseScene
        << ", from the spread of the correctness "
           "renders' "
        << r.seeds << " seeds,\n  at most " << r.maxNoiseRatio
        << " times the reference solution's (a correct lab only)\n"
        << "  lab 6 also: on " << StrategyScene << ", " << StrategySeeds << " seeds of "
        << StrategySpp << " spp at " << StrategyWidth << "x" << StrategyHeight
        << ", each plate tile's variance at most " << MaxStrategyTileRatio
        << " times\n  the better of the reference solution's light and lobe strategies "
           "alone\n";

    out << "\nspeed: at least " << r.minSpeedRatio
        << " times the reference solution's samples per CPU-second, in the correctness renders "
           "of "
        << r.speedScene << " run again,\n  interleaved with the reference's, " << r.speedRuns
        << " pairs at a time up to " << SpeedPairsCap * r.speedRuns
        << "; failed only when below with confidence\n  (a correct lab at the threshold fails "
           "with probability at most "
        << r.speedAlpha << "; undecided at the end, it passes)\n  judged by:";
    for (Lab lab : AllLabs)
        out << " " << labName(lab) << " "
            << (r.forLab(lab).speedJudgedBy == SpeedMeasure::Efficiency ? "efficiency"
                                                                        : "samples/s")
            << (lab == AllLabs.back() ? "" : ",");
    out << "\n\nlimits: " << r.secondsPerRun << " s of CPU time per render thread, "
        << r.secondsPerRun / 2 << " s without a finished sample, "
        << r.secondsPerRun * WallLimitFactor
        << " s of wall-clock time at most\n  (none depends on how busy the machine is), "
        << (r.memoryBytes >> 20) << " MB of memory\n";
    if (r.late.given) {
        std::set<std::string> extended;
        for (const auto& [id, days] : r.late.extensionDays) extended.insert(id);
        for (const auto& [id, labs] : r.late.labExtensionDays) extended.insert(id);
        const size_t extensions = extended.size();
        out << "\nlate: " << r.late.slipDays
            << (r.late.perLab() ? " slip day(s) per student for the term, spent as the labs "
                                  "come due,\n  then "
                                : " slip day(s) per student, then ")
            << r.late.penaltyPerDay * 100
            << (r.late.perLab() ? "% of a late lab's points per late day, at most "
                                : "% of the total per late day, at most ")
            << r.late.maxPenalty * 100 << "%"
            << (extensions == 0 ? std::string()
                                : "; extensions for " + std::to_string(extensions) + " student(s)")
            << "\n";
        // The labs' deadlines in the order they come due.
        std::vector<std::pair<long long, std::string>> due;
        for (const auto& [lab, deadline] : r.late.labDeadlines) due.push_back({deadline, lab});
        std::sort(due.begin(), due.end());
        for (const auto& [deadline, lab] : due)
            out << "  " << lab << " due " << isoTime(deadline) << "\n";
    }
    if (r.lowerScores != LowerScores::Undecided)
        out << "regrades: " << lowerScoresName(r.lowerScores)
            << (r.lowerScores == LowerScores::Replace ? " (a regrade's lower total counts)"
                                                      : " (the higher total of the same files "
                                                        "counts)")
            << "\n";
    return out.str();
}

} // namespace pathlab::grader
