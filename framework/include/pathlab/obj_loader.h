#pragma once
/// Wavefront .obj/.mtl loading into a Scene.

#include "pathlab/scene.h"

#include <string>

namespace pathlab {

/// Appends the triangles and materials of `objPath` (and the .mtl files it names) to `scene`.
/// Throws InputError "file:line: problem" for a malformed line, a missing file or an index out of
/// range; prints a note for MTL keys PathLab ignores and a warning for a material whose
/// Kd+Ks+Kt exceeds 1 in some channel.
void loadObj(const std::string& objPath, Scene& scene);

} // namespace pathlab
