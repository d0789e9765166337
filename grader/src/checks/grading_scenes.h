#pragma once
/// The scenes a grading uses and what each is compared with.

#include "checks/grader_setup.h"

#include <string>
#include <vector>

namespace pathlab::grader {

/// models/NAME.ecs: a public scene of the rubric.
std::string publicScenePath(const std::string& name);

/// The files of every public scene the rubric names (its correctness scenes, its noise and speed
/// scenes, its variants' box), sorted, each once: what a release carrying the rubric must hold.
std::vector<std::string> rubricSceneFiles(const Rubric& rubric);

/// Where the instructor keeps hidden scenes: grader/hidden_scenes/. Every command that grades
/// uses it unless told otherwise (--scenes DIR, --scenes none).
std::string defaultHiddenScenesFolder();

/// The .ecs files of a hidden-scenes folder, sorted; throws InputError if it is not a folder
/// or holds none.
std::vector<std::string> hiddenScenePaths(const std::string& folder);

struct SceneSources {
    std::string references;    ///< stored references of the rubric's public scenes
    std::string hidden;        ///< a folder of hidden .ecs scenes ("": none)
    std::string cache;         ///< where references measured here are kept ("": nowhere)
    bool revealHidden = false; ///< feedback may name hidden scenes and show their images
};

/// The rubric's public scenes (models/NAME.ecs) with their stored references, then the parameter
/// check's furnace (analytic), the glossy furnaces for the labs that write a lobe (analytic), then
/// the hidden scenes with references measured from the solutions `solution` runs. Measured
/// references are kept in the cache and taken from there while the scene files, rubric and kit they
/// were made from are unchanged, so a batch measures each scene once. A public scene without a
/// stored reference is measured too, with a note in `notes`; one whose stored reference is stale
/// stops the grading (InputError) with the command that remakes it.
std::vector<GradingScene> gradingScenes(const Rubric& rubric, const SceneSources& sources,
                                        const LabRunner& solution, const std::string& scratch,
                                        std::vector<std::string>& notes);

/// The reference of the scene at `path` from `cacheFolder` while it fits the scene's files, the
/// rubric and the kit, else measured now from the solutions `solution` runs (and kept there;
/// "" keeps it nowhere). `shownName` names it on the progress bar.
SceneReference cachedOrMeasuredReference(const LabRunner& solution, const std::string& path,
                                         const Rubric& rubric, const std::string& scratch,
                                         const std::string& cacheFolder,
                                         const std::string& shownName);

/// One fingerprint of every scene a grading uses (the files of the public and hidden scenes, the
/// rubric's settings a reference depends on, the kit's version), without measuring anything:
/// each result records it beside the rubric's hash. With per-student variants, the class secret's
/// text too: a new secret draws every student's scenes anew.
std::string scenesHash(const Rubric& rubric, const std::string& hiddenFolder);

} // namespace pathlab::grader
