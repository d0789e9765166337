#pragma once
/// The times an LMS reports (--times), which override those a submission tells of itself. (Times
/// as text, parseTime and isoTime, are common/local_time.h's.)

#include "common/local_time.h"

#include <map>
#include <optional>
#include <string>

namespace pathlab::grader {

/// The times an LMS recorded: a submission's, or one lab's where the LMS has an assignment per lab.
struct SubmissionTimes {
    std::map<std::string, long long> whole;                        ///< id -> submitted at
    std::map<std::string, std::map<std::string, long long>> byLab; ///< id -> lab name -> at
    bool empty() const { return whole.empty() && byLab.empty(); }
};

/// A CSV of lines id,submitted_at or id,lab,submitted_at (a first line "id,..." is its header);
/// throws InputError naming the file and line of anything it cannot read, a lab's name included.
SubmissionTimes loadSubmissionTimes(const std::string& path);

} // namespace pathlab::grader
