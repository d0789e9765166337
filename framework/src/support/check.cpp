#include "pathlab/support/check.h"

#include <filesystem>

namespace pathlab {

namespace {

/// `file` as the user would type it from where the program runs (labs/branching.cpp, or
/// ../labs/branching.cpp from build/), so a terminal or an editor can open it; as compiled
/// (absolute) when it lies further away.
std::string shown(const char* file) {
    namespace fs = std::filesystem;
    std::error_code error;
    // The build names its files from the kit's folder (labs/branching.cpp: no host path in the
    // programs, cmake/compiler_flags.cmake): from build/ that is one folder up.
    if (fs::path(file).is_relative()) {
        if (fs::exists(file, error)) return file;
        if (fs::exists(fs::path("..") / file, error))
            return (fs::path("..") / file).generic_string();
        return file;
    }
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
