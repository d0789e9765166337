#pragma once
/// Line-by-line checks of .obj and .mtl files, so every malformed line is reported by file and
/// line.

#include <string>
#include <vector>

namespace pathlab {

/// Checks `objPath` and the .mtl files it names: the shape of every line (numbers where numbers
/// belong), face indices in range, mtllib files present, usemtl names defined. Throws InputError
/// "file:line: problem" at the first fault. Prints a note for MTL keys PathLab reads and ignores
/// (Ns, illum, textures, ...) and a warning for a material with Kd+Ks+Kt > 1 in some channel.
void validateObj(const std::string& objPath);

/// Checks one .mtl file as above and returns the names of the materials it defines.
std::vector<std::string> validateMtl(const std::string& mtlPath);

} // namespace pathlab
