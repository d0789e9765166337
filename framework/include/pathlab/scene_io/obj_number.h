#pragma once
/// The numbers of an OBJ file's v, vn and vt lines, read as tinyobjloader reads them: every word
/// that starts with a number is one, so that a file other tools open opens here too.

#include <optional>
#include <string_view>

namespace pathlab {

/// How a word of a v/vn/vt line became its number.
enum class ObjNumberReading {
    exact,       ///< the whole word is a decimal number within float's range ("1e-300" is 0)
    leadingPart, ///< a number with more after it ("3.1+e2", "1.#IND"): its leading number
    notFinite,   ///< "nan", "inf", "-INF": 0, as tinyobjloader reads them
    beyondFloat, ///< a decimal number too large for a float ("1e+308"): 0, like nan and inf
};

struct ObjNumber {
    float value = 0;
    ObjNumberReading reading = ObjNumberReading::exact;
};

/// `word` as tinyobjloader would read it, or nothing when it does not start with a number
/// ("zero", "x1", ""): that stays an error.
std::optional<ObjNumber> readObjNumber(std::string_view word);

} // namespace pathlab
