#pragma once
/// Times as text: the time now on this machine's clock, as the batch's log, its lock and the
/// reference figures write it; a deadline's or an LMS's time read; a time in UTC for gradebooks.

#include <optional>
#include <string>

namespace pathlab::grader {

/// The local time now in strftime's `format`: by default "2026-12-06T10:54:20".
std::string localTimeNow(const char* format = "%Y-%m-%dT%H:%M:%S");

/// "2026-12-01T23:59", with optional seconds, and Z or ±HH:MM (else local time), as seconds
/// since 1970; nullopt if it is not such a time.
std::optional<long long> parseTime(const std::string& text);

/// "2026-12-01T22:59:00Z".
std::string isoTime(long long seconds);

} // namespace pathlab::grader
