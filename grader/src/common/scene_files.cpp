#include "common/scene_files.h"

#include "common/content_hash.h"

#include "pathlab/support/input_error.h"
#include "pathlab/scene_io/input_notes.h"
#include "pathlab/scene_io/obj_reading.h"
#include "pathlab/render/render_options.h"

#include <filesystem>

namespace pathlab::grader {

namespace {

namespace fs = std::filesystem;

/// The material libraries an .obj names on its `mtllib` lines that exist, found as the viewer
/// finds them (beside it; a name with spaces whole).
std::vector<std::string> materialLibraries(const std::string& objPath) {
    InputNotes notes; // what the viewer would warn of is the render's to print, not this list's
    std::vector<std::string> libraries;
    for (const std::string& file : readObj(objPath, notes).libraryFiles)
        libraries.push_back(fs::absolute(file).string());
    return libraries;
}

} // namespace

std::vector<std::string> sceneFiles(const std::string& ecsPath) {
    const char* argv[] = {"scene", "-c", ecsPath.c_str()};
    const RenderOptions options = parseRenderOptions(3, argv);
    std::vector<std::string> files;
    for (const std::string& script : options.sceneScripts)
        files.push_back(fs::absolute(script).string());
    for (const std::string& obj : options.objFiles) {
        files.push_back(fs::absolute(obj).string());
        for (const std::string& mtl : materialLibraries(obj)) files.push_back(mtl);
    }
    return files;
}

std::string sceneFilesHash(const std::string& ecsPath) {
    const fs::path folder = fs::absolute(ecsPath).parent_path();
    ContentHash hash;
    for (const std::string& file : sceneFiles(ecsPath))
        hash.add(fs::absolute(file).lexically_relative(folder).generic_string()).addFile(file);
    return hash.hex();
}

} // namespace pathlab::grader
