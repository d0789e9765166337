#pragma once
/// PathLab's reading of an .mtl file: as lenient as tinyobjloader, each liberty it takes named in
/// a warning or note; the values as tinyobjloader read them from the lines as PathLab takes them
/// (mtl_values.h).

#include "pathlab/material.h"
#include "pathlab/scene_io/input_notes.h"

#include <string>
#include <vector>

namespace pathlab {

/// A material library as PathLab reads it.
struct MaterialLibrary {
    /// The materials' names, in the order the library defines them: the whole rest of the
    /// 'newmtl' line, trimmed, spaces inside kept ("" for a 'newmtl' without a name).
    std::vector<std::string> names;
    /// The materials of `names`: Kd, Ks, Kt (from Kt or Tf), Ni and Ke read from each line as
    /// PathLab takes it (a lone "Kd 0.5" as grey, a negative colour as 0, an absurd Ni as 1, a
    /// 'Tf' of a material that says it is opaque left out), numbers as tinyobjloader read them.
    std::vector<Material> materials;
    /// "FILE:LINE: problem" where PathLab and tinyobjloader would read another count of
    /// materials (a lone CR within a line starting a 'newmtl'), which the OBJ file that names
    /// the library then fails with; else empty.
    std::string refusal;
};

/// Reads the .mtl at `mtlPath`. Throws InputError only when it cannot be read or looks like
/// UTF-16; everything else it reads as tinyobjloader does or better, telling `notes`.
MaterialLibrary readMaterialLibrary(const std::string& mtlPath, InputNotes& notes);

} // namespace pathlab
