#pragma once
/// What the kit's programs (viewer, grader, bench) do with an error that reaches main: say it on
/// stderr after the program's name, and exit with the status their users' scripts test.

#include "pathlab/support/input_error.h"

#include <cstdio>
#include <exception>
#include <utility>

namespace pathlab {

/// The exit status of `body()`, which returns one; or, if it throws, the status for what it threw
/// after printing it: bad input (InputError: a file, an option, a scene) "PROGRAM: message" and 2;
/// anything else "PROGRAM: error: message" and `failureStatus`.
template <class Body> int runMain(const char* program, Body&& body, int failureStatus = 1) {
    try {
        return std::forward<Body>(body)();
    } catch (const InputError& error) {
        std::fprintf(stderr, "%s: %s\n", program, error.what());
        return 2;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "%s: error: %s\n", program, error.what());
        return failureStatus;
    }
}

} // namespace pathlab
