#pragma once
/// Errors in what the user gave us: a scene file, an option, an output path.

#include <stdexcept>
#include <string>

namespace pathlab {

/// A problem with the user's input. The message names the file (and line) or the option, and
/// is printed as it is; the program then exits with status 2.
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// "file:line: message", the form compilers use, so editors can jump to it.
inline InputError inputErrorAt(const std::string& file, int line, const std::string& message) {
    return InputError(file + ":" + std::to_string(line) + ": " + message);
}

} // namespace pathlab
