#include "checks/correctness_renders.h"

#include <algorithm>

namespace pathlab::grader {

RenderRequest correctnessRequest(const GraderSetup& setup, const GradingScene& scene, Lab lab,
                                 uint64_t seedBase, const LabRunner& runner) {
    const Rubric& r = setup.rubric;
    // All seeds in one viewer process: its start-up, longer than a small render, is paid once.
    const LabParameters parameters =
        scene.parameters.value_or(LabParameters{r.maxDepth, r.continueProb});
    return {&runner,
            scene.path,
            requestedIdentity(runner, lab, parameters, seedBase, r.width, r.height),
            r.forLab(lab).correctnessSpp,
            r.seeds,
            setup.threads,
            setup.scratch};
}

const GradingScene* speedScene(const GraderSetup& setup) {
    const auto scene = std::find_if(setup.scenes.begin(), setup.scenes.end(), [&](const auto& s) {
        return !s.hidden && !s.parameters && s.reference.scene == setup.rubric.speedScene;
    });
    return scene == setup.scenes.end() ? nullptr : &*scene;
}

} // namespace pathlab::grader
