#pragma once
// What a test reads in a message: whether it says something, and what a call's error said.
#include <string>
#include <utility>

inline bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

/// The message of the `Error` that `call()` throws, or "" if it throws none.
template <class Error, class Call> std::string messageOf(Call&& call) {
    try {
        std::forward<Call>(call)();
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}
