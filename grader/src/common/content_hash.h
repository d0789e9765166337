#pragma once
/// A fingerprint of bytes (files, settings) that tells whether what a stored result was made from
/// has changed since. Not cryptographic: the inputs are the instructor's own files, so only
/// accidental changes need catching.

#include <cstdint>
#include <string>
#include <string_view>

namespace pathlab::grader {

/// 64-bit FNV-1a over everything added, in order; each piece is length-prefixed, so ("ab", "c")
/// and ("a", "bc") differ.
class ContentHash {
public:
    ContentHash& add(std::string_view bytes);
    /// The file's bytes; throws InputError naming it if it cannot be read.
    ContentHash& addFile(const std::string& path);
    /// 16 hex digits.
    std::string hex() const;

private:
    void mix(std::string_view bytes);
    uint64_t state_ = 14695981039346656037ull;
};

} // namespace pathlab::grader
