#pragma once
/// PathLab's reading of an .obj file and the .mtl files it names, in one pass: what would make a
/// wrong mesh is an error naming its file:line; everything else is read as tinyobjloader reads
/// it, or more consistently, each liberty named in a warning or note. The geometry and the
/// materials come out of the same pass (obj_geometry.h, mtl_values.h).

#include "pathlab/material.h"
#include "pathlab/scene_io/input_notes.h"
#include "pathlab/scene_io/obj_geometry.h"

#include <string>
#include <vector>

namespace pathlab {

/// An .obj file as PathLab reads it.
struct ObjReading {
    /// Its triangles, whose material indexes `materials`.
    ObjGeometry geometry;
    /// Every material of the libraries read, library by library in the order the 'mtllib'
    /// lines first name them, each library's in its own order: a name defined twice is there
    /// twice, and a 'usemtl' selects the first.
    std::vector<Material> materials;
    std::vector<std::string> materialNames; ///< same order as `materials`
    /// The path of each material library read, in that order, as found beside the .obj (a name
    /// with spaces whole, where a file of that name is there).
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
