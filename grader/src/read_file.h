#pragma once
/// A whole file read into memory, as the grader reads what it hashes, compares and embeds.

#include <string>

namespace pathlab::grader {

/// The bytes of the file at `path`, unchanged (binary); throws InputError naming the file if it
/// cannot be opened. (Its writing counterpart is writeFileAtomically, pathlab/render_stats.h.)
std::string readFile(const std::string& path);

} // namespace pathlab::grader
