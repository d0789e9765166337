#pragma once
/// Reads options and their values from the command line and the .ecs files it names, reporting
/// errors where a token came from (the option, or file:line).

#include "pathlab/scene_io/scene_script.h"
#include "pathlab/vec3.h"

#include <string>
#include <vector>

namespace pathlab {

/// Walks the tokens, expanding -c files in place, and reports errors where a token came from.
class OptionReader {
public:
    explicit OptionReader(std::vector<Token> tokens) : tokens_(std::move(tokens)) {}

    bool done() const { return next_ >= tokens_.size(); }
    const Token& take() { return tokens_[next_++]; }

    /// Inserts a scene script's tokens right after the -c that named it.
    void includeScript(const std::string& path, int depth);

    /// The value after the current option, or an error naming the option.
    const Token& value(const Token& option, const char* what);

    float number(const Token& option, const char* what = "a number");

    long long integer(const Token& option, const char* what = "an integer");

    Vec3 vec3(const Token& option);

    /// A path given after `option`: relative to the scene script that gave it, or as typed.
    std::string path(const Token& option);

    /// A whole number in 1..max after `option`.
    int positive(const Token& option, const char* what, long long max);

    [[noreturn]] static void fail(const Token& where, const std::string& message);

    const Token& current() const { return tokens_[next_ - 1]; }

private:
    std::vector<Token> tokens_;
    size_t next_ = 0;
};

} // namespace pathlab
