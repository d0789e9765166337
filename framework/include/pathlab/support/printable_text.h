#pragma once
/// Words from the user's files, safe to print: a scene file may hold any bytes, and a message
/// that echoes one of its words must not send a control byte or broken UTF-8 to the terminal.

#include <string>
#include <string_view>

namespace pathlab {

/// `text` with printable ASCII and valid UTF-8 kept as they are and every other byte (control
/// characters, the C1 controls U+0080..U+009F, bytes of invalid or overlong UTF-8) written as
/// \xNN: "r\x01d" for the bytes 'r', 0x01, 'd'.
std::string printableText(std::string_view text);

} // namespace pathlab
