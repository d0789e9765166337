#pragma once
/// The fields of an OBJ or MTL line read exactly as tinyobjloader 2.0.0rc10 reads them, which
/// PathLab's scenes were loaded through until it read them itself: a scene loads bit for bit as
/// it did. Its decimal parser sums digit × 10^-k in double, which is not correctly rounded
/// (strtof gives another last bit for some numbers), and its fields end at space, tab or CR
/// only; both are kept here as they were.

namespace pathlab::objfields {

/// Space or tab: the only characters that separate an OBJ or MTL line's fields here.
inline bool isSpace(char c) { return c == ' ' || c == '\t'; }

/// The number starting at `*token` (after spaces and tabs), as far as it is one, or `fallback`
/// where none starts there; `*token` moves past the field.
float real(const char** token, double fallback = 0.0);

/// As real(), but false (and `*out` unchanged) where no number starts at `*token`.
bool real(const char** token, float* out);

} // namespace pathlab::objfields
