#pragma once
/// The text files a scene is made of (.ecs, .obj, .mtl), read as PathLab reads them all: UTF-8 or
/// ASCII, with or without a byte-order mark, any line ends.

#include <string>
#include <string_view>
#include <vector>

namespace pathlab {

/// The text of the file at `path`, a UTF-8 byte-order mark at its start removed. Throws
/// InputError "PATH: cannot open WHAT" ("the OBJ file") when it cannot be read, and
/// "PATH: looks like UTF-16 text (save it as UTF-8 or ASCII)" when it starts with a UTF-16
/// byte-order mark or has NUL bytes in its first lines, which a text editor's "Unicode" writes
/// and which no reader of the format expects.
std::string readTextFile(const std::string& path, const std::string& what);

/// The lines of `text`, split at '\n', each without its '\r' of a CRLF line end; the last line
/// needs no line end.
std::vector<std::string_view> textLines(std::string_view text);

/// One line of an OBJ or MTL file that holds more than a comment.
struct WordLine {
    int number = 0;                      ///< 1-based
    std::string_view text;               ///< as in the file, comment included
    std::vector<std::string_view> words; ///< split at white space, up to a '#' that begins a word
    std::string_view rest;               ///< what follows the first word, up to that '#', trimmed
};

/// The lines of `text` that hold more than white space and a comment (from a '#' that begins a
/// word to the line's end).
std::vector<WordLine> wordLines(std::string_view text);

} // namespace pathlab
