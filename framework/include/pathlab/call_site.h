#pragma once
/// Where a lab called the API: filled in by the compiler, so that a check that fails inside the
/// framework names the lab's own line rather than the framework's.

namespace pathlab {

/// The file and line of a call. As a defaulted last parameter (`CallSite caller = {}`) it holds
/// the caller's position: the compiler evaluates __builtin_FILE() and __builtin_LINE() (GCC,
/// clang, MSVC 2019 16.6 and later) where the default argument is used, at the call.
struct CallSite {
    const char* file;
    int line;
    constexpr CallSite(const char* file = __builtin_FILE(), int line = __builtin_LINE())
        : file(file), line(line) {}
};

} // namespace pathlab
