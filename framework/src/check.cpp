#include "pathlab/check.h"

#include <filesystem>

namespace pathlab {

namespace {

/// `file` as the user would type it from where the program runs (labs/branching.cpp, or
/// ../labs/branching.cpp from build/), so a terminal or an editor can open it; as compiled
/// (absolute) when it lies further away.
std::string shown(const char* file) {
    namespace fs = std::filesystem;
    std::error_code error;
    const fs::path here = fs::current_path(error);
    if (error) return file;
    const fs::path relative = fs::path(file).lexically_relative(here);
    int upward = 0;
    for (const fs::path& part : relative) upward += part == "..";
    if (relative.empty() || upward > 1) return file;
    return relative.generic_string();
}

} // namespace

void failCheck(const char* file, int line, const char* expression, const std::string& lookAt) {
    throw CheckFailure(shown(file) + ":" + std::to_string(line) + ": check failed: " + expression +
                       ": " + lookAt);
}

void failCheckCalledFrom(CallSite caller, const char* file, int line, const char* expression,
                         const std::string& lookAt) {
    throw CheckFailure(shown(caller.file) + ":" + std::to_string(caller.line) +
                       ": check failed: " + lookAt + " [" + shown(file) + ":" +
                       std::to_string(line) + ": " + expression + "]");
}

} // namespace pathlab
