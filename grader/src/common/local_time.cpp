#include "common/local_time.h"

#include <cstdio>
#include <ctime>

namespace pathlab::grader {

std::string localTimeNow(const char* format) {
    char text[64];
    const std::time_t now = std::time(nullptr);
    std::tm local{};
    localtime_r(&now, &local);
    std::strftime(text, sizeof text, format, &local);
    return text;
}

std::optional<long long> parseTime(const std::string& text) {
    int year = 0, month = 0, day = 0, hour = 0, minute = 0, second = 0, used = 0;
    if (std::sscanf(text.c_str(), "%4d-%2d-%2dT%2d:%2d%n", &year, &month, &day, &hour, &minute,
                    &used) != 5)
        return std::nullopt;
    std::string rest = text.substr(static_cast<size_t>(used));
    if (rest.size() >= 3 && rest[0] == ':') {
        int more = 0;
        if (std::sscanf(rest.c_str(), ":%2d%n", &second, &more) != 1) return std::nullopt;
        rest = rest.substr(static_cast<size_t>(more));
    }
    if (month < 1 || month > 12 || day < 1 || day > 31 || hour > 23 || minute > 59 || second > 60)
        return std::nullopt;
    std::tm fields{};
    fields.tm_year = year - 1900, fields.tm_mon = month - 1, fields.tm_mday = day;
    fields.tm_hour = hour, fields.tm_min = minute, fields.tm_sec = second;
    // 2026-02-30 is not a day: timegm would carry it into March.
    std::tm check = fields;
    const std::time_t asUtc = timegm(&check);
    std::tm back{};
    gmtime_r(&asUtc, &back);
    if (back.tm_mday != day || back.tm_mon != month - 1) return std::nullopt;
    if (rest.empty()) {
        fields.tm_isdst = -1; // local time, daylight saving as it was on that day
        return static_cast<long long>(std::mktime(&fields));
    }
    long long offset = 0;
    if (rest != "Z") {
        int offsetHours = 0, offsetMinutes = 0;
        if ((rest[0] != '+' && rest[0] != '-') ||
            std::sscanf(rest.c_str() + 1, "%2d:%2d", &offsetHours, &offsetMinutes) != 2 ||
            rest.size() != 6)
            return std::nullopt;
        offset = (rest[0] == '-' ? -1 : 1) * (offsetHours * 3600LL + offsetMinutes * 60LL);
    }
    return static_cast<long long>(timegm(&fields)) - offset;
}

std::string isoTime(long long seconds) {
    const std::time_t t = static_cast<std::time_t>(seconds);
    std::tm utc{};
    gmtime_r(&t, &utc);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
    return text;
}

} // namespace pathlab::grader
