#pragma once
// Catch2 v2 (Debian 12) and v3 (Ubuntu 24.04, Homebrew) behind one include.
#if __has_include(<catch2/catch_test_macros.hpp>)
#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
using Catch::Approx;
#else
#include <catch2/catch.hpp>
#endif
// A test case that cannot run here says why: v3.3 and later report it skipped (SKIP); before,
// it warns with the reason and returns, passing.
#ifdef SKIP
#define PATHLAB_SKIP(reason) SKIP(reason)
#else
#define PATHLAB_SKIP(reason)                                                                       \
    do {                                                                                           \
        WARN(reason);                                                                              \
        return;                                                                                    \
    } while (false)
#endif
