#pragma once
/// What a gradebook row's times cost it under the rubric's late policy: against the batch's one
/// deadline, the submission's time; against a deadline per lab, each lab's own time (the LMS's
/// for that lab, else the LMS's for the submission, else the last commit that changed the lab's
/// file or its modification time), with the slip days one budget across the labs.

#include "reports/gradebook.h"

#include <optional>
#include <string>
#include <utility>

namespace pathlab::grader {

/// When a result was submitted (seconds since 1970) and how that is known; 0 when unknown.
std::pair<long long, std::string> submittedAt(const GradebookEntry& e, const GradingNow& now);

struct LateCost {
    int daysLate = 0;     ///< a submission's late days; under deadlines per lab, its labs' summed
    int slipDaysUsed = 0; ///< of the policy's slip days
    double penalty = 0;   ///< the fraction of the graded total it loses
    std::string labs;     ///< under deadlines per lab, the late labs in words
    /// Handed in with no time known (none the submission could tell, none from --times): not
    /// taken as on time, said in the gradebook instead.
    bool timeUnknown = false;
};

/// What the entry's times cost it; none where no deadline applies or no time is known.
std::optional<LateCost> lateCostOf(const GradebookEntry& e, const GradingNow& now);

} // namespace pathlab::grader
