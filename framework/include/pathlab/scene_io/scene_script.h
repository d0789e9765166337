#pragma once
/// Tokens of Embree's scene-script (.ecs) format and of the command line, with where they came
/// from.

#include <string>
#include <vector>

namespace pathlab {

/// One whitespace-separated word and where it was read, so errors can point at it.
struct Token {
    std::string text;
    std::string file; ///< the .ecs file, or empty for the command line
    int line = 0;     ///< 1-based line in `file`
};

/// The tokens of an .ecs file: options and values separated by white space, `#` to the end of a
/// line is a comment. Throws InputError if the file cannot be read.
std::vector<Token> readSceneScript(const std::string& path);

/// The command-line arguments as tokens.
std::vector<Token> commandLineTokens(int argc, const char* const* argv);

} // namespace pathlab
