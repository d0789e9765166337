#include "convergence_reference.h"

#include "pathlab/support/this_process.h"

#include <exception>
#include <system_error>

namespace pathlab::viewer {

namespace {

/// The scene and size `make reference` makes without being told: the window's default.
bool isDefaultWindow(const RenderOptions& options, int width, int height) {
    return options.sceneName == "cornell_box_VI2_Specular" && width == 512 && height == 512;
}

std::string size(int width, int height) {
    return std::to_string(width) + "x" + std::to_string(height);
}

} // namespace

std::filesystem::path cachedReferencePath(const std::string& scene, int width, int height) {
    return thisProgram().parent_path() / "references" /
           (scene + "." + size(width, height) + ".exr");
}

std::string howToMakeReference(const RenderOptions& options, int width, int height) {
    const std::string cached = cachedReferencePath(options.sceneName, width, height).string();
    if (isDefaultWindow(options, width, height))
        return "no reference yet: `make reference` renders one (4096 spp, about 8 minutes on 2 "
               "cores) into " +
               cached + ", which the window then finds";
    const std::string scene =
        options.sceneScripts.empty() ? options.sceneName + ".ecs" : options.sceneScripts.front();
    return "no reference of " + options.sceneName + " at " + size(width, height) +
           ": make one with `viewer -c " + scene + " --size " + std::to_string(width) + " " +
           std::to_string(height) + " --lab roulette --continue-prob 0.8 --spp 4096 -o " + cached +
           "` (add --solution where the reference solutions are) and open the window "
           "again";
}

ConvergenceReference findConvergenceReference(const RenderOptions& options,
                                              const std::string& referenceFile, const Image& given,
                                              int width, int height) {
    ConvergenceReference found;
    if (given.width == width && given.height == height) {
        found.image = given;
        found.file = referenceFile;
        return found;
    }
    if (given.width > 0)
        found.missing = "--reference " + referenceFile + " is " + size(given.width, given.height) +
                        ", the image " + size(width, height) + "; ";
    const std::filesystem::path cached = cachedReferencePath(options.sceneName, width, height);
    std::error_code absent;
    if (std::filesystem::is_regular_file(cached, absent)) {
        try {
            Image image = readImage(cached.string());
            if (image.width == width && image.height == height) {
                found.image = std::move(image);
                found.file = cached.string();
                return found;
            }
        } catch (const std::exception& e) {
            found.missing = std::string(e.what()) + "; ";
        }
    }
    found.missing += howToMakeReference(options, width, height);
    return found;
}

} // namespace pathlab::viewer
