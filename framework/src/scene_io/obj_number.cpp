#include "pathlab/scene_io/obj_number.h"

#include <algorithm>
#include <cctype>
#include <cfloat>
#include <cmath>
#include <locale>
#include <sstream>
#include <string>

namespace pathlab {

namespace {

/// The whole of `text` as a decimal number, in long double so that float's underflow ("5e-310")
/// and overflow ("1e+308") are numbers to be judged rather than parse failures.
std::optional<long double> wholeDecimal(std::string_view text) {
    if (text.empty() ||
        !(std::isdigit(static_cast<unsigned char>(text.back())) || text.back() == '.'))
        return std::nullopt; // "1e", "1-": a stream would read "1" and stop before the end
    std::istringstream stream{std::string(text)};
    stream.imbue(std::locale::classic());
    long double value = 0;
    if (!(stream >> value) || stream.peek() != std::char_traits<char>::eof()) return std::nullopt;
    return value;
}

bool startsWithNonFinite(std::string_view word) {
    if (!word.empty() && (word[0] == '+' || word[0] == '-')) word.remove_prefix(1);
    if (word.size() < 3) return false;
    std::string head(word.substr(0, 3));
    for (char& c : head) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return head == "nan" || head == "inf";
}

std::optional<ObjNumber> fromDecimal(long double value, ObjNumberReading reading) {
    if (!std::isfinite(value)) return ObjNumber{0.0f, ObjNumberReading::notFinite};
    if (std::fabs(value) > FLT_MAX) return ObjNumber{0.0f, ObjNumberReading::beyondFloat};
    return ObjNumber{static_cast<float>(value), reading};
}

} // namespace

std::optional<ObjNumber> readObjNumber(std::string_view word) {
    if (startsWithNonFinite(word)) return ObjNumber{0.0f, ObjNumberReading::notFinite};
    if (const auto whole = wholeDecimal(word)) return fromDecimal(*whole, ObjNumberReading::exact);
    // tinyobjloader reads as far as a number goes and stops: the longest prefix that is one.
    // Numbers are short: a longer word's leading part is looked for in its first 64 characters.
    for (size_t length = std::min(word.size(), size_t{64}); length-- > 1;) {
        if (const auto leading = wholeDecimal(word.substr(0, length))) {
            return fromDecimal(*leading, ObjNumberReading::leadingPart);
        }
    }
    return std::nullopt;
}

} // namespace pathlab
