#pragma once
/// Numbers and lists read from text (options, scene scripts, OBJ/MTL files), the same on every
/// platform.

#include <optional>
#include <string_view>
#include <vector>

namespace pathlab {

/// `text` as a float when the whole of it is one decimal number ("0.8", "-1e-3", "+2"), else
/// nothing. Independent of the locale ("1,5" is never a number) and of the standard library:
/// std::from_chars where it parses floats, a classic-locale stream where it does not (libc++
/// before version 20, Apple's included). Infinities and NaN are not numbers here.
std::optional<float> parseFloat(std::string_view text);

/// The pieces of `text` between `separator`s, empty ones included: "2,4,8" -> {"2", "4", "8"},
/// "a,,b" -> {"a", "", "b"}, "" -> {""}. For options that take a list, like --shard's or
/// --timing-cpus' values.
std::vector<std::string_view> splitAt(std::string_view text, char separator);

} // namespace pathlab
