#include "pathlab/scene_io/option_reader.h"

#include "pathlab/support/input_error.h"
#include "pathlab/support/parse_number.h"
#include "pathlab/support/printable_text.h"

#include <charconv>
#include <filesystem>
#include <optional>

namespace pathlab {

namespace fs = std::filesystem;

void OptionReader::includeScript(const std::string& path, int depth) {
    if (depth > 8) fail(current(), "scene scripts include each other more than 8 deep");
    std::vector<Token> script = readSceneScript(path);
    tokens_.insert(tokens_.begin() + static_cast<std::ptrdiff_t>(next_), script.begin(),
                   script.end());
}

const Token& OptionReader::value(const Token& option, const char* what) {
    // In a scene script an option's values sit on its line, so a short one is caught there.
    const bool missing = done() || (!option.file.empty() && (tokens_[next_].line != option.line ||
                                                             tokens_[next_].file != option.file));
    if (missing) fail(option, "option " + option.text + " needs " + what);
    return take();
}

float OptionReader::number(const Token& option, const char* what) {
    const Token& t = value(option, what);
    const std::optional<float> v = parseFloat(t.text);
    if (!v) fail(option, "option " + option.text + " expects " + what + ", got '" + t.text + "'");
    return *v;
}

long long OptionReader::integer(const Token& option, const char* what) {
    const Token& t = value(option, what);
    long long v = 0;
    const char* end = t.text.data() + t.text.size();
    auto [ptr, ec] = std::from_chars(t.text.data(), end, v);
    if (ec != std::errc() || ptr != end)
        fail(option, "option " + option.text + " expects " + what + ", got '" + t.text + "'");
    return v;
}

Vec3 OptionReader::vec3(const Token& option) {
    const float x = number(option, "three numbers x y z");
    const float y = number(option, "three numbers x y z");
    const float z = number(option, "three numbers x y z");
    return {x, y, z};
}

std::string OptionReader::path(const Token& option) {
    const Token& t = value(option, "a file name");
    if (t.file.empty() || fs::path(t.text).is_absolute()) return t.text;
    return (fs::path(t.file).parent_path() / t.text).lexically_normal().string();
}

void OptionReader::fail(const Token& where, const std::string& message) {
    // The message echoes a word of a file or the command line, which may be any bytes.
    if (where.file.empty()) throw InputError(printableText(message));
    throw inputErrorAt(printableText(where.file), where.line, printableText(message));
}

int OptionReader::positive(const Token& option, const char* what, long long max) {
    const long long v = integer(option, what);
    if (v < 1 || v > max)
        fail(option, "option " + option.text + " expects " + what + " (1.." + std::to_string(max) +
                         "), got " + std::to_string(v));
    return static_cast<int>(v);
}

} // namespace pathlab
