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

} // namespace pathlab
