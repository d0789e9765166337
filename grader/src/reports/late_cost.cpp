#include "reports/late_cost.h"

#include "pathlab/render/lab_registry.h"

#include <map>

namespace pathlab::grader {

namespace {

nlohmann::json intakeOf(const GradebookEntry& e) {
    return e.result.value("intake", nlohmann::json::object());
}

/// Each handed-in lab's time (lab name -> seconds since 1970), the LMS's over the submission's;
/// the labs handed in with no time known go into `unknown`.
std::map<std::string, long long> labTimesOf(const GradebookEntry& e, const GradingNow& now,
                                            std::vector<std::string>& unknown) {
    const nlohmann::json intake = intakeOf(e);
    const nlohmann::json taken = intake.value("taken", nlohmann::json::object());
    // Results graded before labs had their own times have only the submission's.
    const auto ownTimes = intake.value("lab_times", std::map<std::string, long long>{});
    const auto lmsLabs = now.times.byLab.find(e.id);
    const auto lmsWhole = now.times.whole.find(e.id);
    std::map<std::string, long long> times;
    for (Lab lab : AllLabs) {
        const std::string name(labName(lab)), file = labFileName(lab);
        if (!taken.contains(file)) continue; // not handed in: never late
        long long at = intake.value("submitted_at", 0LL);
        if (const auto own = ownTimes.find(file); own != ownTimes.end()) at = own->second;
        if (lmsWhole != now.times.whole.end()) at = lmsWhole->second;
        if (lmsLabs != now.times.byLab.end())
            if (const auto lms = lmsLabs->second.find(name); lms != lmsLabs->second.end())
                at = lms->second;
        if (at != 0)
            times[name] = at;
        else
            unknown.push_back(name);
    }
    return times;
}

std::optional<LateCost> perLabCost(const GradebookEntry& e, const GradingNow& now) {
    std::vector<std::string> unknown;
    const std::vector<LabLateness> labs =
        labLatenessOf(now.late, e.id, labTimesOf(e, now, unknown), now.deadline);
    if (labs.empty() && unknown.empty()) return std::nullopt;
    std::map<std::string, double> scores;
    const nlohmann::json graded = e.result.value("labs", nlohmann::json::object());
    for (const auto& [lab, result] : graded.items()) scores[lab] = result.value("score", 0.0);
    LateCost cost;
    for (const LabLateness& lab : labs) {
        cost.daysLate += lab.late.daysLate;
        cost.slipDaysUsed += lab.late.slipDaysUsed;
    }
    cost.penalty = totalPenalty(labs, scores);
    cost.labs = lateLabsText(labs);
    // A lab with no time is not taken as on time: the gradebook says so, for --times to settle.
    for (const std::string& lab : unknown) {
        cost.timeUnknown = true;
        cost.labs += (cost.labs.empty() ? "" : ", ") + lab + ": no time known";
    }
    return cost;
}

} // namespace

std::pair<long long, std::string> submittedAt(const GradebookEntry& e, const GradingNow& now) {
    if (const auto given = now.times.whole.find(e.id); given != now.times.whole.end())
        return {given->second, "--times"};
    if (e.result.is_null()) return {0, ""};
    const nlohmann::json intake = intakeOf(e);
    return {intake.value("submitted_at", 0LL), intake.value("time_source", "")};
}

std::optional<LateCost> lateCostOf(const GradebookEntry& e, const GradingNow& now) {
    if (now.late.perLab()) return e.result.is_null() ? std::nullopt : perLabCost(e, now);
    const long long at = submittedAt(e, now).first;
    if (!now.deadline) return std::nullopt;
    if (at == 0) {
        if (e.result.is_null()) return std::nullopt;
        LateCost unknown;
        unknown.timeUnknown = true;
        return unknown;
    }
    const Lateness late = latenessOf(now.late, e.id, at, *now.deadline);
    return LateCost{late.daysLate, late.slipDaysUsed, late.penalty, ""};
}

} // namespace pathlab::grader
