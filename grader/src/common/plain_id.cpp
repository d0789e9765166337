#include "common/plain_id.h"

#include <cctype>

namespace pathlab::grader {

std::string plainId(const std::string& name) {
    std::string id;
    for (char c : name)
        id += std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-' ? c
                                                                                              : '_';
    return id.empty() || id[0] == '.' ? "submission" + id : id;
}

} // namespace pathlab::grader
