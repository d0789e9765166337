#include "checks/late_policy.h"

#include "common/local_time.h"
#include "common/plain_id.h"
#include "pathlab/render/lab_registry.h"
#include "pathlab/support/parse_number.h"
#include "pathlab/support/input_error.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

namespace pathlab::grader {

namespace {

constexpr long long kSecondsPerDay = 24 * 60 * 60;

/// id,days lines (every deadline of the student's moves) and id,days,lab lines (that lab's), after
/// an optional header "id,...", each id as the grader spells it.
void readExtensions(const std::string& path, LatePolicy& policy) {
    std::ifstream in(path);
    if (!in) throw InputError(path + ": cannot open the late policy's extensions");
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty() || (number == 1 && line.rfind("id,", 0) == 0)) continue;
        std::vector<std::string> fields;
        for (std::string_view field : splitAt(line, ',')) fields.emplace_back(field);
        const std::string where = path + ":" + std::to_string(number) + ": ";
        char* end = nullptr;
        const long value = fields.size() >= 2 ? std::strtol(fields[1].c_str(), &end, 10) : -1;
        if (fields.size() > 3 || fields[0].empty() || fields.size() < 2 || fields[1].empty() ||
            *end != '\0' || value < 0 || value > 365)
            throw InputError(where +
                             "expected id,days or id,days,lab (whole days from 0 to "
                             "365), got '" +
                             line + "'");
        // As the grader spells ids: an email's @ as _ (common/plain_id.h).
        const std::string id = plainId(fields[0]);
        if (fields.size() == 2) {
            policy.extensionDays[id] = static_cast<int>(value);
            continue;
        }
        if (!labFromName(fields[2]))
            throw InputError(where + "'" + fields[2] + "' is not a lab (" + labNames(", ") + ")");
        policy.labExtensionDays[id][fields[2]] = static_cast<int>(value);
    }
}

/// The rubric's "deadlines": {"branching": "2026-10-02T23:59Z", ...}.
std::map<std::string, long long> readLabDeadlines(const nlohmann::json& j,
                                                  const std::string& rubricPath) {
    std::map<std::string, long long> deadlines;
    if (!j.is_object())
        throw InputError(rubricPath + ": late.deadlines maps a lab's name to its deadline, "
                                      "e.g. {\"branching\": \"2026-10-02T23:59Z\"}");
    for (const auto& [lab, when] : j.items()) {
        if (!labFromName(lab))
            throw InputError(rubricPath + ": late.deadlines names '" + lab + "', not a lab (" +
                             labNames(", ") + ")");
        const std::optional<long long> seconds =
            when.is_string() ? parseTime(when.get<std::string>()) : std::nullopt;
        if (!seconds)
            throw InputError(rubricPath + ": late.deadlines." + lab + " is " + when.dump() +
                             ", not a time like 2026-10-02T23:59 (local), 2026-10-02T23:59Z or "
                             "2026-10-02T23:59+01:00");
        deadlines[lab] = *seconds;
    }
    return deadlines;
}

/// The days `id`'s deadline for `lab` moves: its extension for that lab, else its extension.
int extensionOf(const LatePolicy& policy, const std::string& id, const std::string& lab) {
    if (const auto labs = policy.labExtensionDays.find(id); labs != policy.labExtensionDays.end())
        if (const auto days = labs->second.find(lab); days != labs->second.end())
            return days->second;
    const auto days = policy.extensionDays.find(id);
    return days == policy.extensionDays.end() ? 0 : days->second;
}

/// Whole days from `due` to `submittedAt`, rounded up; 0 if on time. At most a century: a
/// time far off (the student's clock sets a commit's) must not wrap into negative days, which
/// would hand out slip days.
int daysAfter(long long submittedAt, long long due) {
    if (submittedAt <= due) return 0;
    constexpr long long Century = 36525;
    return static_cast<int>(
        std::min(Century, (submittedAt - due + kSecondsPerDay - 1) / kSecondsPerDay));
}

double penaltyFor(const LatePolicy& policy, const Lateness& late) {
    return std::min(policy.maxPenalty, (late.daysLate - late.slipDaysUsed) * policy.penaltyPerDay);
}

} // namespace

LatePolicy readLatePolicy(const nlohmann::json& j, const std::string& rubricPath) {
    LatePolicy policy;
    if (j.is_null()) return policy;
    policy.given = true;
    policy.penaltyPerDay = j.value("penalty_per_day", 0.0);
    policy.maxPenalty = j.value("max_penalty", 1.0);
    policy.slipDays = j.value("slip_days", 0);
    if (!(policy.penaltyPerDay >= 0 && policy.penaltyPerDay <= 1) ||
        !(policy.maxPenalty >= 0 && policy.maxPenalty <= 1) || policy.slipDays < 0)
        throw InputError(rubricPath + ": late needs penalty_per_day and max_penalty between 0 "
                                      "and 1 (fractions of the total) and slip_days >= 0");
    if (j.contains("extensions")) {
        const std::filesystem::path file = j.at("extensions").get<std::string>();
        readExtensions(
            (file.is_absolute() ? file : std::filesystem::path(rubricPath).parent_path() / file)
                .string(),
            policy);
    }
    if (j.contains("deadlines"))
        policy.labDeadlines = readLabDeadlines(j.at("deadlines"), rubricPath);
    if (!policy.labExtensionDays.empty() && !policy.perLab())
        throw InputError(rubricPath + ": the extensions give a lab's own extension "
                                      "(id,days,lab), which needs a deadline per lab: "
                                      "late.deadlines");
    return policy;
}

nlohmann::json latePolicyJson(const LatePolicy& policy) {
    if (!policy.given) return nullptr;
    return {{"penalty_per_day", policy.penaltyPerDay},
            {"max_penalty", policy.maxPenalty},
            {"slip_days", policy.slipDays},
            {"extension_days", policy.extensionDays},
            {"lab_deadlines", policy.labDeadlines},
            {"lab_extension_days", policy.labExtensionDays}};
}

LatePolicy latePolicyFromJson(const nlohmann::json& kept) {
    LatePolicy policy;
    if (!kept.is_object()) return policy;
    policy.given = true;
    policy.penaltyPerDay = kept.value("penalty_per_day", 0.0);
    policy.maxPenalty = kept.value("max_penalty", 1.0);
    policy.slipDays = kept.value("slip_days", 0);
    policy.extensionDays = kept.value("extension_days", std::map<std::string, int>{});
    policy.labDeadlines = kept.value("lab_deadlines", std::map<std::string, long long>{});
    policy.labExtensionDays =
        kept.value("lab_extension_days", std::map<std::string, std::map<std::string, int>>{});
    return policy;
}

Lateness latenessOf(const LatePolicy& policy, const std::string& id, long long submittedAt,
                    long long deadline) {
    Lateness late;
    const auto extension = policy.extensionDays.find(id);
    const long long due =
        deadline +
        (extension == policy.extensionDays.end() ? 0 : extension->second) * kSecondsPerDay;
    late.daysLate = daysAfter(submittedAt, due);
    late.slipDaysUsed = std::min(late.daysLate, policy.slipDays);
    late.penalty = penaltyFor(policy, late);
    return late;
}

std::vector<LabLateness> labLatenessOf(const LatePolicy& policy, const std::string& id,
                                       const std::map<std::string, long long>& labTimes,
                                       std::optional<long long> otherwise) {
    struct Due {
        long long deadline;
        Lab lab;
    };
    std::vector<Due> dues;
    for (Lab lab : AllLabs) {
        const std::string name(labName(lab));
        const auto own = policy.labDeadlines.find(name);
        if (own != policy.labDeadlines.end())
            dues.push_back({own->second, lab});
        else if (otherwise)
            dues.push_back({*otherwise, lab});
    }
    // The slip days go to the late labs in the order they were due, as a student spends them.
    std::stable_sort(dues.begin(), dues.end(),
                     [](const Due& a, const Due& b) { return a.deadline < b.deadline; });
    std::vector<LabLateness> labs;
    int slipDaysLeft = policy.slipDays;
    for (const Due& due : dues) {
        const std::string name(labName(due.lab));
        const auto handedIn = labTimes.find(name);
        if (handedIn == labTimes.end()) continue;
        LabLateness lab{name, {}};
        lab.late.daysLate = daysAfter(
            handedIn->second, due.deadline + extensionOf(policy, id, name) * kSecondsPerDay);
        lab.late.slipDaysUsed = std::min(lab.late.daysLate, slipDaysLeft);
        slipDaysLeft -= lab.late.slipDaysUsed;
        lab.late.penalty = penaltyFor(policy, lab.late);
        labs.push_back(lab);
    }
    return labs;
}

double totalPenalty(const std::vector<LabLateness>& labs,
                    const std::map<std::string, double>& labScores) {
    double total = 0, lost = 0;
    for (const auto& [lab, score] : labScores) total += score;
    for (const LabLateness& lab : labs)
        if (const auto score = labScores.find(lab.lab); score != labScores.end())
            lost += score->second * lab.late.penalty;
    return total > 0 ? lost / total : 0;
}

std::string lateLabsText(const std::vector<LabLateness>& labs) {
    std::string text;
    for (const LabLateness& lab : labs) {
        if (lab.late.daysLate == 0) continue;
        text += (text.empty() ? "" : ", ") + lab.lab + " " + std::to_string(lab.late.daysLate) +
                " day(s) late";
        if (lab.late.slipDaysUsed > 0)
            text += " (" + std::to_string(lab.late.slipDaysUsed) + " slip day(s))";
    }
    return text;
}

} // namespace pathlab::grader
