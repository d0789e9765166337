#pragma once
/// PathLab's reading of an .obj file and the .mtl files it names, before tinyobjloader reads the
/// geometry: what would make a wrong mesh is an error naming its file:line; everything else is
/// read as tinyobjloader reads it, or more consistently, each liberty named in a warning or note.

#include "pathlab/scene_io/input_notes.h"
#include "pathlab/scene_io/mtl_reading.h"

#include <string>
#include <vector>

namespace pathlab {

/// An .obj file as PathLab reads it, ready for tinyobjloader.
struct ObjReading {
    /// The .obj text for tinyobjloader: each 'usemtl' naming its material by
    /// tinyobjMaterialName(), each 'mtllib' naming the index of a library in `libraries`
    /// ("mtllib 0"; one line for each file), unknown keywords left out; geometry as in the file.
    std::string textForTinyobj;
    std::vector<MaterialLibrary> libraries;
    /// The path of each of `libraries`' files, as found beside the .obj (a name with spaces
    /// whole, where a file of that name is there).
    std::vector<std::string> libraryFiles;
    /// A warning already says that some faces are grey (an undefined material, a library not
    /// found), so the note for faces without a material would repeat it.
    bool greyFacesExplained = false;
};

/// Reads `objPath` and the material libraries it names. Throws InputError "FILE:LINE: problem" at
/// the first fault that would change the mesh: a coordinate that is not a number, a face corner
/// that is malformed or out of range, a face of fewer than 3 corners; "FILE: problem" for a file
/// that cannot be read, is UTF-16 or is XML. Tells `notes` of the rest: undefined materials,
/// missing libraries, keywords PathLab ignores, MTL values it reads otherwise.
ObjReading readObj(const std::string& objPath, InputNotes& notes);

} // namespace pathlab
