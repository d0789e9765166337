// grader make-variants: the rubric's variants of the public scenes, written as hidden scenes
// (scene_variants.h), for a grading that is not a batch (Gradescope's autograder, whose setup.sh
// makes them where the instructor keeps no hidden scenes).
#include "checks/scene_variants.h"
#include "commands/commands.h"

#include "pathlab/support/input_error.h"
#include "pathlab/support/whole_file.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>

namespace pathlab::grader {

uint64_t variantSeed(const Arguments& a, const std::string& keptIn) {
    if (a.variantSeed != 0) return a.variantSeed;
    uint64_t kept = 0;
    if (std::ifstream in(keptIn); in >> kept && kept != 0) return kept;
    std::random_device device;
    const uint64_t seed = (uint64_t(device()) << 32 | device()) | 1;
    return seed;
}

int makeVariants(const Arguments& a, const Rubric& rubric) {
    const std::string folder = a.inputs.front();
    if (rubric.sceneVariants <= 0)
        throw InputError(a.rubric + ": hidden_scenes.variants is 0: no variants to make");
    const std::string seedFile = folder + "/seed";
    const uint64_t seed = variantSeed(a, seedFile);
    const std::vector<std::string> written = writeSceneVariants(rubric, folder, seed);
    if (written.empty())
        throw InputError(a.rubric + ": every public scene of the rubric is a furnace, of which no "
                                    "variant is made: add a scene like cornell_box_VI2_Specular "
                                    "to correctness.scenes, or keep hidden scenes");
    writeFileAtomically(seedFile, std::to_string(seed) + "\n");
    for (const std::string& path : written) std::printf("wrote %s\n", path.c_str());
    std::printf("seed %s in %s: keep it from the students, as the scenes themselves\n",
                std::to_string(seed).c_str(), seedFile.c_str());
    return 0;
}

} // namespace pathlab::grader
