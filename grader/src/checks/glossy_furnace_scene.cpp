#include "checks/glossy_furnace_scene.h"

#include "checks/grading_scenes.h"
#include "checks/number_text.h"

#include "common/content_hash.h"

#include "pathlab/random_stream.h"
#include "pathlab/render/render_options.h"
#include "pathlab/render/scene_from_options.h"
#include "pathlab/support/input_error.h"
#include "pathlab/support/whole_file.h"
#include "pathlab/warp/phong_albedo.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace pathlab::grader {

namespace {

namespace fs = std::filesystem;

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

/// The labs the glossy furnaces grade: those that write a lobe.
std::vector<Lab> lobeLabs() {
    std::vector<Lab> labs;
    for (Lab lab : AllLabs)
        if (writesLobe(lab)) labs.push_back(lab);
    return labs;
}

GradingScene analyticScene(const Rubric& rubric, const std::string& name, const std::string& path) {
    GradingScene scene;
    scene.labs = lobeLabs();
    scene.path = path;
    scene.name = name;
    const auto [value, formula] = plateRadiance(scene.path);
    SceneReference& ref = scene.reference;
    ref = referenceHeader(name, rubric, rubric.maxDepth, rubric.continueProb);
    ref.depthLimited = analyticExpectation(rubric, value, formula);
    ref.unbiased = ref.depthLimited;
    return scene;
}

} // namespace

uint64_t labVariantSeed(const GraderSetup& setup, Lab lab) {
    ContentHash hash;
    hash.add(std::to_string(setup.seedBase)).add(labName(lab));
    const std::string& library = setup.student.libraryFor(lab);
    hash.addFile(library.empty() ? setup.student.viewer : library);
    // 48 bits: the viewer's --seed takes it whole.
    return std::stoull(hash.hex(), nullptr, 16) >> 16;
}

GradingScene tiltedGlossyFurnaceVariant(const Rubric& rubric, uint64_t seed,
                                        const std::string& scratch) {
    RandomStream random(seed);
    const float exponent = 6 + 34 * random.nextFloat();
    const double tilt = (35 + 35 * random.nextFloat()) / Degrees;
    const std::string folder = scratch + "/glossy_furnace_variant";
    fs::create_directories(folder);
    const std::string models = std::string(PATHLAB_MODELS_DIR) + "/";
    fs::copy_file(models + "glossy_furnace.obj", folder + "/glossy_furnace.obj",
                  fs::copy_options::overwrite_existing);
    char text[400];
    std::snprintf(text, sizeof text,
                  "newmtl glow\nKe 1 1 1\nnewmtl plate\nKs 0.8 0.8 0.8\nNs %.9g\nillum 2\n",
                  exponent);
    writeFileAtomically(folder + "/glossy_furnace.mtl", text);
    std::snprintf(text, sizeof text,
                  "# glossy_furnace_tilted as this submission is graded on it\n"
                  "-i glossy_furnace.obj\n-vp 0 %.9g %.9g\n-vi 0 0 0\n-vu 0 1 0\n-fov 0.05\n",
                  0.8 * std::sin(tilt), -0.8 * std::cos(tilt));
    const std::string ecs = folder + "/glossy_furnace_tilted.ecs";
    writeFileAtomically(ecs, text);
    return analyticScene(rubric, GlossyFurnaceScenes[1], ecs);
}

std::vector<GradingScene> glossyFurnaceScenes(const Rubric& rubric) {
    std::vector<GradingScene> scenes;
    if (lobeLabs().empty()) return scenes;
    for (const char* name : GlossyFurnaceScenes)
        scenes.push_back(analyticScene(rubric, name, publicScenePath(name)));
    return scenes;
}

} // namespace pathlab::grader
