#pragma once
/// Whole files in and out: what the grader hashes, compares and embeds, and every report, stats
/// file and reference the kit writes.

#include <string>

namespace pathlab {

/// The bytes of the file at `path`, unchanged (binary). Throws InputError naming the file if it
/// cannot be opened.
std::string readFile(const std::string& path);

/// Writes `text` to `path` through a temporary file in the same folder and a rename, so a reader
/// never sees half a file, and an interrupted write leaves the old one whole. Throws InputError
/// naming the file if it cannot be written.
void writeFileAtomically(const std::string& path, const std::string& text);

/// Throws InputError naming the file unless writeFileAtomically(path, ...) could write it now,
/// leaving a file already at `path` as it is: for a program that writes its result after
/// minutes of work, to stop before them.
void checkWritable(const std::string& path);

} // namespace pathlab
