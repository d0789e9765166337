#pragma once
/// The files a scene is made of, and one fingerprint of them: what a reference measured from the
/// scene is keyed by, so that an edited .mtl is never graded against the old light.

#include <string>
#include <vector>

namespace pathlab::grader {

/// The scene's .ecs, every .ecs it includes, the .obj meshes they name and the .mtl libraries
/// those name, in the order the viewer reads them, as absolute paths (a sandboxed render binds
/// exactly these). Throws InputError as the viewer would on a scene it cannot load.
std::vector<std::string> sceneFiles(const std::string& ecsPath);

/// A hash of those files' names (relative to the .ecs's folder) and contents.
std::string sceneFilesHash(const std::string& ecsPath);

} // namespace pathlab::grader
