#include "pathlab/support/printable_text.h"

#include <cstdio>

namespace pathlab {

namespace {

/// The length of the valid, printable UTF-8 sequence at the start of `text`, or 0.
size_t printableUtf8Length(std::string_view text) {
    const auto byte = [&](size_t i) { return static_cast<unsigned char>(text[i]); };
    const unsigned char lead = byte(0);
    size_t length = 0;
    char32_t code = 0;
    if (lead >= 0xC2 && lead <= 0xDF)
        length = 2, code = lead & 0x1F;
    else if (lead >= 0xE0 && lead <= 0xEF)
        length = 3, code = lead & 0x0F;
    else if (lead >= 0xF0 && lead <= 0xF4)
        length = 4, code = lead & 0x07;
    else
        return 0;
    if (text.size() < length) return 0;
    for (size_t i = 1; i < length; ++i) {
        if ((byte(i) & 0xC0) != 0x80) return 0;
        code = (code << 6) | (byte(i) & 0x3F);
    }
    const char32_t least[5] = {0, 0, 0x80, 0x800, 0x10000}; // shorter forms are overlong
    const bool surrogate = code >= 0xD800 && code <= 0xDFFF;
    const bool c1Control = code <= 0x9F;
    if (code < least[length] || surrogate || code > 0x10FFFF || c1Control) return 0;
    return length;
}

} // namespace

std::string printableText(std::string_view text) {
    std::string printable;
    printable.reserve(text.size());
    for (size_t i = 0; i < text.size();) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c >= 0x20 && c < 0x7F) {
            printable += text[i++];
        } else if (const size_t length = printableUtf8Length(text.substr(i)); length > 0) {
            printable.append(text.substr(i, length));
            i += length;
        } else {
            char escaped[5];
            std::snprintf(escaped, sizeof escaped, "\\x%02X", c);
            printable += escaped;
            ++i;
        }
    }
    return printable;
}

} // namespace pathlab
