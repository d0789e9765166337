#pragma once
/// The rubric's late policy (its "late" section): what a submission handed in after the deadline
/// loses. Slip days forgiven per student, a penalty per late day after them, a cap, per-student
/// extensions (a CSV of id,days[,lab] beside the rubric), and optionally a deadline per lab, each
/// lab then late by its own time with the slip days one budget across the labs. It decides the
/// total that counts and nothing of how a lab is graded, so it is left out of the rubric's hash:
/// changing it grades and re-scores nobody.

#include <nlohmann/json.hpp>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace pathlab::grader {

struct LatePolicy {
    bool given = false;       ///< the rubric has a "late" section
    double penaltyPerDay = 0; ///< the fraction of the total lost per late day after slip days
    double maxPenalty = 1;    ///< the most a submission loses, as a fraction of its total
    int slipDays = 0;         ///< late days forgiven, per student
    std::map<std::string, int> extensionDays; ///< id -> days each of its deadlines moves
    /// The rubric's "deadlines": lab name -> its deadline (seconds since 1970). Empty: one deadline
    /// for the whole submission, the batch's --deadline.
    std::map<std::string, long long> labDeadlines;
    /// id -> lab name -> days that lab's deadline moves (the extensions' id,days,lab lines).
    std::map<std::string, std::map<std::string, int>> labExtensionDays;

    bool perLab() const { return !labDeadlines.empty(); }
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

/// One lab's lateness under a deadline per lab; its penalty is a fraction of that lab's score.
struct LabLateness {
    std::string lab;
    Lateness late;
};

/// Under a deadline per lab: the lateness of each of `id`'s labs handed in at `labTimes` (lab
/// name -> seconds since 1970; a lab without a time was not handed in and costs nothing) against
/// its deadline, the policy's for that lab or else `otherwise` (the batch's --deadline; a lab with
/// neither is never late), in the order of their deadlines. The slip days are one budget for the
/// term, spent on the late labs as they come.
std::vector<LabLateness> labLatenessOf(const LatePolicy& policy, const std::string& id,
                                       const std::map<std::string, long long>& labTimes,
                                       std::optional<long long> otherwise);

/// What the late labs cost together: the fraction of the graded total (the sum of `labScores`,
/// lab name -> score) that their penalties take.
double totalPenalty(const std::vector<LabLateness>& labs,
                    const std::map<std::string, double>& labScores);

/// The late labs in words: "uniform 2 day(s) late (1 slip day), roulette 1 day(s) late"; "" if
/// none is.
std::string lateLabsText(const std::vector<LabLateness>& labs);

} // namespace pathlab::grader
