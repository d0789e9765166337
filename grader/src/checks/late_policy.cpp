#include "checks/late_policy.h"

#include "common/plain_id.h"
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

/// id,days lines, after an optional header "id,...", each id as the grader spells it.
std::map<std::string, int> readExtensions(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw InputError(path + ": cannot open the late policy's extensions");
    std::map<std::string, int> days;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty() || (number == 1 && line.rfind("id,", 0) == 0)) continue;
        const size_t comma = line.find(',');
        const std::string id = line.substr(0, comma);
        char* end = nullptr;
        const std::string count = comma == std::string::npos ? "" : line.substr(comma + 1);
        const long value = std::strtol(count.c_str(), &end, 10);
        if (id.empty() || count.empty() || *end != '\0' || value < 0 || value > 365)
            throw InputError(path + ":" + std::to_string(number) +
                             ": expected id,days (whole days from 0 to 365), got '" + line + "'");
        // As the grader spells ids: an email's @ as _ (common/plain_id.h).
        days[plainId(id)] = static_cast<int>(value);
    }
    return days;
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
        policy.extensionDays = readExtensions(
            (file.is_absolute() ? file : std::filesystem::path(rubricPath).parent_path() / file)
                .string());
    }
    return policy;
}

nlohmann::json latePolicyJson(const LatePolicy& policy) {
    if (!policy.given) return nullptr;
    return {{"penalty_per_day", policy.penaltyPerDay},
            {"max_penalty", policy.maxPenalty},
            {"slip_days", policy.slipDays},
            {"extension_days", policy.extensionDays}};
}

LatePolicy latePolicyFromJson(const nlohmann::json& kept) {
    LatePolicy policy;
    if (!kept.is_object()) return policy;
    policy.given = true;
    policy.penaltyPerDay = kept.value("penalty_per_day", 0.0);
    policy.maxPenalty = kept.value("max_penalty", 1.0);
    policy.slipDays = kept.value("slip_days", 0);
    policy.extensionDays = kept.value("extension_days", std::map<std::string, int>{});
    return policy;
}

Lateness latenessOf(const LatePolicy& policy, const std::string& id, long long submittedAt,
                    long long deadline) {
    Lateness late;
    const auto extension = policy.extensionDays.find(id);
    const long long due =
        deadline +
        (extension == policy.extensionDays.end() ? 0 : extension->second) * kSecondsPerDay;
    if (submittedAt <= due) return late;
    late.daysLate = static_cast<int>((submittedAt - due + kSecondsPerDay - 1) / kSecondsPerDay);
    late.slipDaysUsed = std::min(late.daysLate, policy.slipDays);
    late.penalty =
        std::min(policy.maxPenalty, (late.daysLate - late.slipDaysUsed) * policy.penaltyPerDay);
    return late;
}

} // namespace pathlab::grader
