#include "checks/glossy_furnace_scene.h"

#include "checks/grading_scenes.h"
#include "checks/number_text.h"

#include "pathlab/scene_io/obj_loader.h"
#include "pathlab/scene_io/scene.h"
#include "pathlab/support/input_error.h"

namespace pathlab::grader {

std::optional<GradingScene> glossyFurnaceScene(const Rubric& rubric) {
    GradingScene scene;
    for (Lab lab : AllLabs)
        if (writesLobe(lab)) scene.labs.push_back(lab);
    if (scene.labs.empty()) return std::nullopt;
    scene.path = publicScenePath(GlossyFurnaceScene);
    scene.name = GlossyFurnaceScene;
    // The plate's Ks, from the file the labs render: the value cannot drift from the scene.
    Scene loaded;
    const std::string obj = std::string(PATHLAB_MODELS_DIR) + "/" + GlossyFurnaceScene + ".obj";
    loadObj(obj, loaded);
    double ks = -1;
    for (size_t i = 0; i < loaded.materials.size(); ++i)
        if (loaded.materialNames[i] == "plate" && loaded.materials[i].Ns > 0)
            ks = loaded.materials[i].Ks.r;
    if (ks < 0) throw InputError(obj + ": no glossy material 'plate' (illum 2 with Ns)");
    SceneReference& ref = scene.reference;
    ref = referenceHeader(GlossyFurnaceScene, rubric, rubric.maxDepth, rubric.continueProb);
    const std::string formula = "Ks·Le = " + significant(ks, 3) +
                                ", what a glossy plate seen head-on reflects of a glow all round";
    ref.depthLimited = analyticExpectation(rubric, ks, formula);
    ref.unbiased = ref.depthLimited;
    return scene;
}

} // namespace pathlab::grader
