#include "common/local_time.h"

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

} // namespace pathlab::grader
