#pragma once
/// Wavefront .obj/.mtl loading into a Scene.

#include "pathlab/scene_io/scene.h"

#include <string>

namespace pathlab {

/// Appends the triangles and materials of `objPath` (and the .mtl files it names) to `scene`.
/// Reads as leniently as tinyobjloader (obj_reading.h): throws InputError "file:line: problem"
/// only for what would make a wrong mesh (a coordinate that is not a number, a face corner out of
/// range, a face of fewer than 3 corners), "file: problem" for an OBJ file that cannot be read,
/// is UTF-16 or XML, or makes no triangle; prints a warning or note for each liberty it takes
/// (an undefined material, a missing .mtl, MTL values it reads otherwise, keys it ignores) and a
/// warning for a material whose Kd+Ks+Kt exceeds 1 in some channel.
void loadObj(const std::string& objPath, Scene& scene);

} // namespace pathlab
