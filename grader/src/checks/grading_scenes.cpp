#include "checks/grading_scenes.h"

#include "checks/glossy_furnace_scene.h"
#include "checks/student_variant.h"

#include "checks/correctness_check.h"
#include "common/content_hash.h"
#include "common/scene_files.h"

#include "pathlab/support/input_error.h"
#include "pathlab/support/progress_bar.h"

#include <algorithm>
#include <set>
#include <filesystem>

namespace pathlab::grader {

namespace fs = std::filesystem;

std::string publicScenePath(const std::string& name) {
    return std::string(PATHLAB_MODELS_DIR) + "/" + name + ".ecs";
}

namespace {

/// Whether a reference's noise figures were measured at the seeds and samples per pixel the
/// rubric grades at: the noise check compares figures measured alike.
bool noiseMeasuredAsGraded(const SceneReference& reference, const Rubric& rubric) {
    if (reference.noiseSeeds != rubric.seeds) return false;
    for (Lab lab : AllLabs)
        if (reference.noiseSpp[lab] != rubric.forLab(lab).correctnessSpp) return false;
    return true;
}

} // namespace

SceneReference cachedOrMeasuredReference(const LabRunner& solution, const std::string& path,
                                         const Rubric& rubric, const std::string& scratch,
                                         const std::string& cacheFolder,
                                         const std::string& shownName) {
    if (!cacheFolder.empty()) {
        try {
            const SceneReference cached = loadReference(cacheFolder, path, rubric);
            if (noiseMeasuredAsGraded(cached, rubric)) return cached;
        } catch (const InputError&) {
            // Not measured yet, or stale (an edited scene, another rubric): measure it below.
        }
    }
    ProgressBar bar("reference for " + shownName, "renders");
    const SceneReference reference =
        measureReference(solution, path, rubric, 20, 4, scratch,
                         [&](int done, int total) { bar.update(done, total); });
    if (!cacheFolder.empty()) {
        fs::create_directories(cacheFolder);
        saveReference(cacheFolder, reference);
    }
    return reference;
}

std::string defaultHiddenScenesFolder() {
    const std::string folder = std::string(PATHLAB_GRADER_DIR) + "/hidden_scenes";
    std::error_code error;
    for (const auto& entry : fs::directory_iterator(folder, error))
        if (entry.path().extension() == ".ecs") return folder;
    return "";
}

std::vector<std::string> hiddenScenePaths(const std::string& folder) {
    if (!fs::is_directory(folder))
        throw InputError("hidden scenes: '" + folder + "' is not a folder");
    std::vector<std::string> paths;
    for (const auto& entry : fs::directory_iterator(folder))
        if (entry.path().extension() == ".ecs")
            paths.push_back(fs::absolute(entry.path()).string());
    std::sort(paths.begin(), paths.end());
    if (paths.empty()) throw InputError("hidden scenes: no .ecs file in '" + folder + "'");
    return paths;
}

std::vector<GradingScene> gradingScenes(const Rubric& rubric, const SceneSources& sources,
                                        const LabRunner& solution, const std::string& scratch,
                                        std::vector<std::string>& notes) {
    std::vector<GradingScene> scenes;
    for (const std::string& name : rubric.scenes) {
        GradingScene s;
        s.path = publicScenePath(name);
        s.name = name;
        s.furnace = furnaceModel(name, rubric.maxDepth, rubric.continueProb);
        try {
            s.reference = loadReference(sources.references, s.path, rubric);
            if (!noiseMeasuredAsGraded(s.reference, rubric))
                notes.push_back(
                    name +
                    ": the stored noise figures were measured at other seeds or samples "
                    "per pixel than the rubric grades at; `grader make-references "
                    "--only-scene " +
                    name + "` measures them as graded");
        } catch (const StaleReference& e) {
            // Grading against it would fail correct labs (or pass wrong ones): stop instead.
            throw InputError(std::string(e.what()) +
                             ". Remake it: grader make-references --only-scene " + name +
                             " (or restore models/ and the rubric as they were); for a rubric "
                             "of your own, into a copy of grader/references/ that you then "
                             "grade with: grader make-references --only-scene " +
                             name + " --rubric YOURS --references COPY");
        } catch (const InputError& e) {
            notes.push_back(std::string(e.what()) + "; measured on the fly instead");
            s.reference =
                cachedOrMeasuredReference(solution, s.path, rubric, scratch, sources.cache, name);
        }
        scenes.push_back(std::move(s));
    }
    scenes.push_back(parameterCheckScene(rubric));
    for (GradingScene& glossy : glossyFurnaceScenes(rubric)) scenes.push_back(std::move(glossy));
    if (sources.hidden.empty()) return scenes;
    const std::vector<std::string> hidden = hiddenScenePaths(sources.hidden);
    for (size_t i = 0; i < hidden.size(); ++i) {
        GradingScene s;
        s.path = hidden[i];
        s.hidden = !sources.revealHidden;
        s.name =
            s.hidden ? "hidden scene " + std::to_string(i + 1) : fs::path(s.path).stem().string();
        s.reference =
            cachedOrMeasuredReference(solution, s.path, rubric, scratch, sources.cache, s.name);
        scenes.push_back(std::move(s));
    }
    return scenes;
}

std::vector<std::string> rubricSceneFiles(const Rubric& rubric) {
    std::vector<std::string> names = rubric.scenes;
    names.push_back(rubric.noiseScene);
    names.push_back(rubric.speedScene);
    if (!rubric.variants.boxScene.empty()) names.push_back(rubric.variants.boxScene);
    std::set<std::string> files;
    for (const std::string& name : names) {
        if (!fs::exists(publicScenePath(name)))
            throw InputError("the rubric grades on the public scene '" + name + "', but " +
                             publicScenePath(name) +
                             " does not exist: a public scene is found by name in models/ "
                             "(put its .ecs, .obj and .mtl there)");
        for (const std::string& file : sceneFiles(publicScenePath(name))) files.insert(file);
    }
    return {files.begin(), files.end()};
}

std::string scenesHash(const Rubric& rubric, const std::string& hiddenFolder) {
    ContentHash hash;
    hash.add(referenceParametersHash(rubric)).add(PATHLAB_VERSION);
    for (const std::string& name : rubric.scenes)
        hash.add(name).add(sceneFilesHash(publicScenePath(name)));
    if (!hiddenFolder.empty())
        for (const std::string& path : hiddenScenePaths(hiddenFolder))
            hash.add(fs::path(path).filename().string()).add(sceneFilesHash(path));
    if (rubric.variants.perStudent) hash.add(classSecret(rubric.variants));
    if (!rubric.variants.boxScene.empty())
        hash.add(rubric.variants.boxScene)
            .add(sceneFilesHash(publicScenePath(rubric.variants.boxScene)));
    return hash.hex();
}

} // namespace pathlab::grader
