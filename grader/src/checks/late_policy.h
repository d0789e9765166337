#pragma once
/// The rubric's late policy (its "late" section): what a submission handed in after the deadline
/// loses. Slip days forgiven per student, a penalty per late day after them, a cap, and
/// per-student extensions (a CSV of id,days beside the rubric). It decides the total that counts
/// and nothing of how a lab is graded, so it is left out of the rubric's hash: changing it grades
/// and re-scores nobody.

#include <nlohmann/json.hpp>

#include <map>
#include <optional>
#include <string>

namespace pathlab::grader {

struct LatePolicy {
    bool given = false;       ///< the rubric has a "late" section
    double penaltyPerDay = 0; ///< the fraction of the total lost per late day after slip days
    double maxPenalty = 1;    ///< the most a submission loses, as a fraction of its total
    int slipDays = 0;         ///< late days forgiven, per student
    std::map<std::string, int> extensionDays; ///< id -> days its deadline moves
};

/// Reads the rubric's "late" section (`section`; null for none) of the rubric at `rubricPath`,
/// the extensions CSV relative to it; throws InputError naming what is wrong.
LatePolicy readLatePolicy(const nlohmann::json& section, const std::string& rubricPath);

/// The policy as batch.json keeps it for `grader merge` (extensions read in); null if not given.
nlohmann::json latePolicyJson(const LatePolicy& policy);
/// The policy batch.json kept (null: none).
LatePolicy latePolicyFromJson(const nlohmann::json& kept);

/// What a submission's time costs it.
struct Lateness {
    int daysLate = 0;     ///< whole days after its deadline (an extension's included), rounded up
    int slipDaysUsed = 0; ///< of the policy's slip days
    double penalty = 0;   ///< the fraction of its total it loses
};

/// The lateness of `id` handed in at `submittedAt` against `deadline` (seconds since 1970).
Lateness latenessOf(const LatePolicy& policy, const std::string& id, long long submittedAt,
                    long long deadline);

} // namespace pathlab::grader
