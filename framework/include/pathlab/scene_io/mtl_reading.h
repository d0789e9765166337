#pragma once
/// PathLab's reading of an .mtl file: as lenient as tinyobjloader, each liberty it takes named in
/// a warning or note, and the file rewritten so that tinyobjloader reads the same materials.

#include "pathlab/scene_io/input_notes.h"

#include <string>
#include <string_view>
#include <vector>

namespace pathlab {

/// A material library as PathLab reads it.
struct MaterialLibrary {
    /// The .mtl text for tinyobjloader's LoadMtl: every material named by
    /// tinyobjMaterialName(name), numbers PathLab reads otherwise than tinyobjloader would (a
    /// lone "Kd 0.5", a negative colour, an absurd Ni) rewritten, lines before the first
    /// 'newmtl' left out; the rest as in the file, so its numbers read bit for bit as before.
    std::string textForTinyobj;
    /// The materials' names, in the order the library defines them: the whole rest of the
    /// 'newmtl' line, trimmed, spaces inside kept ("" for a 'newmtl' without a name).
    std::vector<std::string> names;
};

/// Reads the .mtl at `mtlPath`. Throws InputError only when it cannot be read or looks like
/// UTF-16; everything else it reads as tinyobjloader does or better, telling `notes`.
MaterialLibrary readMaterialLibrary(const std::string& mtlPath, InputNotes& notes);

/// A material's name as one word, for tinyobjloader, whose 'usemtl' reads one word only: white
/// space, control bytes and '%' written %XX, the empty name "%". Names of printable words stay as
/// they are.
std::string tinyobjMaterialName(std::string_view name);

} // namespace pathlab
