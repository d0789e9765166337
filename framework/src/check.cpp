#include "pathlab/check.h"

namespace pathlab {

void failCheck(const char* file, int line, const char* expression, const std::string& lookAt) {
    throw CheckFailure(std::string(file) + ":" + std::to_string(line) +
                       ": check failed: " + expression + ": " + lookAt);
}

} // namespace pathlab
