#include "checks/glossy_furnace_scene.h"

#include "checks/grading_scenes.h"
#include "checks/number_text.h"

#include "pathlab/render/render_options.h"
#include "pathlab/render/scene_from_options.h"
#include "pathlab/support/input_error.h"
#include "pathlab/warp/phong_albedo.h"

#include <cmath>

namespace pathlab::grader {

namespace {

constexpr double Degrees = 180 / 3.14159265358979323846;

/// The plate's radiance in the scene at `path`, and where it comes from in words: its Ks times
/// the lobe's reflectance at the angle the camera sees it at, from the scene's own files.
std::pair<double, std::string> plateRadiance(const std::string& path) {
    const char* argv[] = {"grader", "-c", path.c_str()};
    const Scene scene = loadScene(parseRenderOptions(3, argv));
    for (size_t t = 0; t < scene.triangles.size(); ++t) {
        const uint32_t material = scene.triangleMaterials[t];
        if (scene.materialNames[material] != "plate" || !(scene.materials[material].Ns > 0))
            continue;
        const Material& m = scene.materials[material];
        const auto& corners = scene.triangles[t];
        const Vec3 a = scene.positions[corners[0]], b = scene.positions[corners[1]],
                   c = scene.positions[corners[2]];
        const Vec3 normal = normalize(cross(b - a, c - a));
        // The view's angle from the normal at the point the camera looks at (on the plate).
        const Vec3 toCamera = normalize(scene.camera->position - scene.camera->lookAt);
        const double tilt = std::acos(std::fmin(1.0, std::fabs(double(dot(toCamera, normal)))));
        const double reflectance = phongGlowReflectance(m.Ns, tilt);
        const double value = m.Ks.r * reflectance;
        const std::string angle = significant(tilt * Degrees, 3);
        return {value, tilt < 1e-3 ? "Ks·Le = " + significant(value, 4) +
                                         ", what a glossy plate seen head-on reflects of a glow "
                                         "all round"
                                   : "Ks·Le·ρ = " + significant(value, 4) +
                                         ", ρ = " + significant(reflectance, 4) +
                                         " the lobe's reflectance above the surface seen at " +
                                         angle + " degrees (a mirror would show Ks·Le)"};
    }
    throw InputError(path + ": no glossy material 'plate' (illum 2 with Ns)");
}

} // namespace

std::vector<GradingScene> glossyFurnaceScenes(const Rubric& rubric) {
    std::vector<Lab> labs;
    for (Lab lab : AllLabs)
        if (writesLobe(lab)) labs.push_back(lab);
    std::vector<GradingScene> scenes;
    if (labs.empty()) return scenes;
    for (const char* name : GlossyFurnaceScenes) {
        GradingScene scene;
        scene.labs = labs;
        scene.path = publicScenePath(name);
        scene.name = name;
        const auto [value, formula] = plateRadiance(scene.path);
        SceneReference& ref = scene.reference;
        ref = referenceHeader(name, rubric, rubric.maxDepth, rubric.continueProb);
        ref.depthLimited = analyticExpectation(rubric, value, formula);
        ref.unbiased = ref.depthLimited;
        scenes.push_back(std::move(scene));
    }
    return scenes;
}

} // namespace pathlab::grader
