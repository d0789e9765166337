#include "pathlab/support/parse_number.h"

#include <algorithm>
#include <cmath>
#include <locale>
#include <sstream>
#include <string>
#include <version>

#if defined(__cpp_lib_to_chars)
#include <charconv>
#endif

namespace pathlab {

std::optional<float> parseFloat(std::string_view text) {
    // from_chars takes no sign '+', which OBJ writers and people do write.
    if (text.size() > 1 && text[0] == '+' && text[1] != '-' && text[1] != '+')
        text.remove_prefix(1);
    if (text.empty() || std::isspace(static_cast<unsigned char>(text[0]))) return std::nullopt;
    float value = 0;
#if defined(__cpp_lib_to_chars)
    const char* end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, value);
    if (error != std::errc() || stop != end) return std::nullopt;
#else
    std::istringstream stream{std::string(text)};
    stream.imbue(std::locale::classic());
    if (!(stream >> value) || stream.peek() != std::char_traits<char>::eof()) return std::nullopt;
#endif
    if (!std::isfinite(value)) return std::nullopt;
    return value;
}

std::vector<std::string_view> splitAt(std::string_view text, char separator) {
    std::vector<std::string_view> pieces;
    for (size_t at = 0;;) {
        const size_t end = std::min(text.find(separator, at), text.size());
        pieces.push_back(text.substr(at, end - at));
        if (end == text.size()) return pieces;
        at = end + 1;
    }
}

} // namespace pathlab
