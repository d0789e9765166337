// Catch2 v2 needs its main() compiled in one file; v3 links Catch2::Catch2WithMain instead.
#if !__has_include(<catch2/catch_test_macros.hpp>)
#define CATCH_CONFIG_MAIN
// Lines as long as the messages: Catch2 wraps at 80 columns by default, splitting numbers and
// paths ("0.\n  500000"). (Catch2 v3's library is built with its own width, which stays.)
#define CATCH_CONFIG_CONSOLE_WIDTH 400
#include <catch2/catch.hpp>
#endif
