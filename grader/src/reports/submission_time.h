#pragma once
/// Submission times for the gradebook: ISO 8601 text, the instructor's deadline, and the times an
/// LMS reports (--times), which override those a submission tells of itself.

#include <map>
#include <optional>
#include <string>

namespace pathlab::grader {

/// "2026-12-01T23:59", with optional seconds, and Z or ±HH:MM (else local time), as seconds
/// since 1970; nullopt if it is not such a time.
std::optional<long long> parseTime(const std::string& text);

/// "2026-12-01T22:59:00Z".
std::string isoTime(long long seconds);

/// A CSV of id,submitted_at (a first line "id,..." is its header); throws InputError naming the
/// file and line of anything it cannot read.
std::map<std::string, long long> loadSubmissionTimes(const std::string& path);

} // namespace pathlab::grader
