#include "pathlab/support/text_file.h"

#include "pathlab/support/input_error.h"
#include "pathlab/support/printable_text.h"

#include <filesystem>
#include <fstream>
#include <algorithm>
#include <iterator>

namespace pathlab {

namespace {

// A UTF-16 file of ASCII text has a NUL in every other byte; a few lines are enough to tell.
constexpr size_t firstLinesBytes = 1024;

bool looksLikeUtf16(std::string_view text) {
    const bool bom = text.size() >= 2 && ((text[0] == '\xFF' && text[1] == '\xFE') ||
                                          (text[0] == '\xFE' && text[1] == '\xFF'));
    return bom || text.substr(0, firstLinesBytes).find('\0') != std::string_view::npos;
}

} // namespace

std::string readTextFile(const std::string& path, const std::string& what) {
    std::ifstream in(path, std::ios::binary);
    if (!in || std::filesystem::is_directory(path))
        throw InputError(printableText(path) + ": cannot open " + what);
    std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (in.bad()) throw InputError(printableText(path) + ": read error");
    if (looksLikeUtf16(text))
        throw InputError(printableText(path) +
                         ": looks like UTF-16 text (save it as UTF-8 or ASCII)");
    if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
    return text;
}

std::vector<std::string_view> textLines(std::string_view text) {
    std::vector<std::string_view> lines;
    for (size_t start = 0; start < text.size();) {
        size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(start, end - start);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        lines.push_back(line);
        start = end + 1;
    }
    return lines;
}

namespace {

constexpr std::string_view space = " \t\r\v\f";

/// Where a line's comment starts: a '#' that begins a word. One inside a word is part of it, as
/// tinyobjloader reads "1.#IND" (MSVC's NaN) or a material named "red#2".
size_t commentStart(std::string_view line) {
    for (size_t at = line.find('#'); at != std::string_view::npos; at = line.find('#', at + 1))
        if (at == 0 || space.find(line[at - 1]) != std::string_view::npos) return at;
    return line.size();
}

} // namespace

std::vector<WordLine> wordLines(std::string_view text) {
    std::vector<WordLine> lines;
    int number = 0;
    for (const std::string_view line : textLines(text)) {
        ++number;
        const std::string_view content = line.substr(0, commentStart(line));
        WordLine words{number, line, {}, {}};
        for (size_t at = content.find_first_not_of(space); at != std::string_view::npos;) {
            const size_t end = std::min(content.find_first_of(space, at), content.size());
            words.words.push_back(content.substr(at, end - at));
            if (words.words.size() == 1 && end < content.size()) {
                const size_t first = content.find_first_not_of(space, end);
                if (first != std::string_view::npos) {
                    const size_t last = content.find_last_not_of(space);
                    words.rest = content.substr(first, last + 1 - first);
                }
            }
            at = content.find_first_not_of(space, end);
        }
        if (!words.words.empty()) lines.push_back(std::move(words));
    }
    return lines;
}

} // namespace pathlab
