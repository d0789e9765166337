#pragma once
/// The time now on this machine's clock, as the batch's log, its lock and the reference figures
/// write it (a time in UTC, for gradebooks, is reports/submission_time.h's isoTime).

#include <string>

namespace pathlab::grader {

/// The local time now in strftime's `format`: by default "2026-12-06T10:54:20".
std::string localTimeNow(const char* format = "%Y-%m-%dT%H:%M:%S");

} // namespace pathlab::grader
