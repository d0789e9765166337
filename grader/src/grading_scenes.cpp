#include "grading_scenes.h"

#include "correctness_check.h"
#include "progress_bar.h"

#include "pathlab/input_error.h"

#include <algorithm>
#include <filesystem>

namespace pathlab::grader {

namespace {

namespace fs = std::filesystem;

SceneReference measured(const LabRunner& solution, const std::string& path, const Rubric& rubric,
                        const std::string& scratch, const std::string& cacheFolder) {
    const std::string name = fs::path(path).stem().string();
    if (!cacheFolder.empty()) {
        try {
            return loadReference(cacheFolder, name, rubric);
        } catch (const InputError&) {
            // Not measured yet (or for another rubric): measure it below.
        }
    }
    ProgressBar bar("reference for " + name, "renders");
    const SceneReference reference = measureReference(
        solution, path, rubric, 20, 4, scratch, [&](int done, int total) { bar.update(done, total); });
    if (!cacheFolder.empty()) {
        fs::create_directories(cacheFolder);
        saveReference(cacheFolder, reference);
    }
    return reference;
}

} // namespace

std::vector<GradingScene> gradingScenes(const Rubric& rubric, const std::string& referencesFolder,
                                        const std::string& hiddenFolder,
                                        const std::string& cacheFolder, const LabRunner& solution,
                                        const std::string& scratch, std::vector<std::string>& notes) {
    std::vector<GradingScene> scenes;
    for (const std::string& name : rubric.scenes) {
        GradingScene s{std::string(PATHLAB_MODELS_DIR) + "/" + name + ".ecs", {},
                       furnaceModel(name, rubric.maxDepth, rubric.continueProb), std::nullopt};
        try {
            s.reference = loadReference(referencesFolder, name, rubric);
        } catch (const InputError& e) {
            notes.push_back(std::string(e.what()) + "; measured on the fly instead");
            s.reference = measured(solution, s.path, rubric, scratch, cacheFolder);
        }
        scenes.push_back(std::move(s));
    }
    scenes.push_back(parameterCheckScene(rubric));
    if (hiddenFolder.empty()) return scenes;
    if (!fs::is_directory(hiddenFolder))
        throw InputError("option --scenes: '" + hiddenFolder + "' is not a folder");
    std::vector<fs::path> hidden;
    for (const auto& entry : fs::directory_iterator(hiddenFolder))
        if (entry.path().extension() == ".ecs") hidden.push_back(fs::absolute(entry.path()));
    std::sort(hidden.begin(), hidden.end());
    if (hidden.empty()) throw InputError("option --scenes: no .ecs file in '" + hiddenFolder + "'");
    for (const fs::path& path : hidden)
        scenes.push_back({path.string(), measured(solution, path.string(), rubric, scratch, cacheFolder),
                          std::nullopt, std::nullopt});
    return scenes;
}

} // namespace pathlab::grader
