#pragma once
/// PATHLAB_CHECK and PATHLAB_DCHECK: a condition that must hold, checked where a bug would
/// first show, reported with the expression, the file and line, and what to look at.

#include "pathlab/call_site.h"

#include <stdexcept>
#include <string>

namespace pathlab {

/// A broken check. Its message is "file:line: check failed: EXPRESSION: what to look at", the
/// form compilers use, so an editor jumps to the line. The viewer and the tests print it and
/// stop: a condition that does not hold would only give a wrong image further on.
class CheckFailure : public std::logic_error {
public:
    using std::logic_error::logic_error;
};

/// Throws the CheckFailure for a check at file:line.
[[noreturn]] void failCheck(const char* file, int line, const char* expression,
                            const std::string& lookAt);

/// Throws the CheckFailure for a check at file:line of the framework that a lab's call at
/// `caller` broke: the lab's line comes first, the framework's check last.
[[noreturn]] void failCheckCalledFrom(CallSite caller, const char* file, int line,
                                      const char* expression, const std::string& lookAt);

} // namespace pathlab

/// Always checked, in every build: conditions a lab's code can break (a helper given a missed
/// hit, a direction that is not unit length). `lookAt` says what to fix, in the student's words.
#define PATHLAB_CHECK(condition, lookAt)                                                           \
    do {                                                                                           \
        if (!(condition)) ::pathlab::failCheck(__FILE__, __LINE__, #condition, lookAt);            \
    } while (false)

/// PATHLAB_CHECK for a function of the student API that was given `caller`: the message starts
/// with the lab's file and line, where the mistake is.
#define PATHLAB_CHECK_CALLER(condition, caller, lookAt)                                            \
    do {                                                                                           \
        if (!(condition))                                                                          \
            ::pathlab::failCheckCalledFrom(caller, __FILE__, __LINE__, #condition, lookAt);        \
    } while (false)

/// Checked in debug builds and in the sanitizer builds (PATHLAB_DEBUG_CHECKS=ON): the
/// framework's own invariants, too costly or too certain to test in every sample of a
/// release build. The condition is still compiled (not evaluated) otherwise, so it cannot rot.
#if !defined(NDEBUG) || defined(PATHLAB_DEBUG_CHECKS)
#define PATHLAB_DCHECK(condition) PATHLAB_CHECK(condition, "an invariant of the framework")
#else
#define PATHLAB_DCHECK(condition)                                                                  \
    do {                                                                                           \
        if (false && (condition)) {                                                                \
        }                                                                                          \
    } while (false)
#endif
