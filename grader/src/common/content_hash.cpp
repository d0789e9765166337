#include "common/content_hash.h"

#include "pathlab/support/whole_file.h"

#include <cstdio>

namespace pathlab::grader {

void ContentHash::mix(std::string_view bytes) {
    for (const char c : bytes) {
        state_ ^= static_cast<unsigned char>(c);
        state_ *= 1099511628211ull;
    }
}

ContentHash& ContentHash::add(std::string_view bytes) {
    mix(std::to_string(bytes.size()) + ":");
    mix(bytes);
    return *this;
}

ContentHash& ContentHash::addFile(const std::string& path) { return add(readFile(path)); }

std::string ContentHash::hex() const {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(state_));
    return text;
}

} // namespace pathlab::grader
