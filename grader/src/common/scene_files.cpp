#include "common/scene_files.h"

#include "common/content_hash.h"

#include "pathlab/input_error.h"
#include "pathlab/render_options.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace pathlab::grader {

namespace {

namespace fs = std::filesystem;

/// The material libraries an .obj names on its `mtllib` lines that exist (tinyobjloader looks
/// for them beside it).
std::vector<std::string> materialLibraries(const std::string& objPath) {
    std::ifstream in(objPath);
    if (!in) throw InputError(objPath + ": cannot be read");
    std::vector<std::string> libraries;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::string key, name;
        if (!(words >> key) || key != "mtllib") continue;
        while (words >> name)
            if (const fs::path mtl = fs::absolute(fs::path(objPath).parent_path() / name);
                fs::exists(mtl))
                libraries.push_back(mtl.string());
    }
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
