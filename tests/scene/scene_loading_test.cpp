// Loading scenes: PathLab's models, Embree's own Cornell box, and the OBJ/MTL/ECS features used.
#include "catch.h"
#include "test_support.h"

#include "pathlab/scene_io/obj_loader.h"
#include "pathlab/render/render_options.h"
#include "pathlab/render/scene_from_options.h"

#include <filesystem>
#include <fstream>

using namespace pathlab;
using pathlab::test::modelPath;

namespace {

RenderOptions optionsFor(const std::vector<std::string>& arguments) {
    std::vector<const char*> argv = {"viewer"};
    for (const std::string& a : arguments) argv.push_back(a.c_str());
    return parseRenderOptions(static_cast<int>(argv.size()), argv.data());
}

void writeFile(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

size_t emissiveTriangles(const Scene& scene) {
    size_t n = 0;
    for (uint32_t m : scene.triangleMaterials) n += !isBlack(scene.materials[m].Ke);
    return n;
}

// A copy, not a reference: a reference returned from a call given a temporary (the name's
// std::string) is what GCC 14's -Wdangling-reference warns about.
Material materialNamed(const Scene& scene, const std::string& name) {
    for (size_t i = 0; i < scene.materials.size(); ++i)
        if (scene.materialNames[i] == name) return scene.materials[i];
    FAIL("no material " << name);
    throw;
}

} // namespace

TEST_CASE("the VI2 Cornell box loads with its camera, glass, mirror and area light", "[scene]") {
    const RenderOptions options = optionsFor({"-c", modelPath("cornell_box_VI2_Specular.ecs")});
    CHECK(options.sceneName == "cornell_box_VI2_Specular");
    REQUIRE(options.cameraSet);
    CHECK(options.camera.position.z == Approx(-800));
    CHECK(options.camera.fovDegrees == Approx(37));
    const Scene scene = loadScene(options);
    CHECK(scene.triangles.size() > 100);
    CHECK(emissiveTriangles(scene) == 2);
    bool glass = false, mirror = false;
    for (const Material& m : scene.materials) {
        glass |= reduceMax(m.Kt) > 0.5f && m.Ni == Approx(1.5f);
        mirror |= reduceMax(m.Ks) > 0.5f && isBlack(m.Kt);
    }
    CHECK(glass);
    CHECK(mirror);
}

TEST_CASE("PathLab's scenes load without notes or warnings", "[scene][solutions]") {
    for (const char* scene :
         {"cornell_box_VI2_Specular.ecs", "cornell_box_diffuse.ecs", "furnace.ecs",
          "furnace_a08.ecs", "furnace_mirror.ecs", "furnace_glass.ecs", "refraction_check.ecs"}) {
        const std::string image = test::temporaryFolder("quiet") + "/out.png";
        const auto run = test::runViewer("-c " + modelPath(scene) +
                                         " --size 8 8 --spp 1 --lab "
                                         "importance --solution -o " +
                                         image);
        INFO(scene << ": " << run.output);
        CHECK(run.exitStatus == 0);
        CHECK(run.output.find("warning") == std::string::npos);
        CHECK(run.output.find("note") == std::string::npos);
    }
}

TEST_CASE("Embree's own cornell_box.ecs loads unchanged, point light included", "[scene]") {
    const std::string embreeBox = PATHLAB_EMBREE_MODELS_DIR "/cornell_box.ecs";
    if (!std::filesystem::exists(embreeBox))
        PATHLAB_SKIP(embreeBox << " is missing: Embree's models come with embree-tools");
    const RenderOptions options = optionsFor({"-c", embreeBox});
    REQUIRE(options.pointLights.size() == 1);
    CHECK(options.pointLights[0].position.y == Approx(300));
    CHECK(options.pointLights[0].intensity.r == Approx(100000));
    const Scene scene = loadScene(options);
    CHECK(scene.triangles.size() == 34); // 17 quads
    CHECK(scene.camera.has_value());
}

TEST_CASE("OBJ features: quads, negative indices, normals, Kt/Tf, Ni, Ke, default material",
          "[scene]") {
    const std::string dir = test::temporaryFolder("obj-features");
    writeFile(dir + "/m.mtl", "newmtl glass\nKt 0.9 0.8 0.7\nNi 1.33\n"
                              "newmtl filter\nTf 0.5 0.5 0.5\n"
                              "newmtl lamp\nKe 2 3 4\n");
    writeFile(dir + "/a.obj", "mtllib m.mtl\n"
                              "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\n"
                              "usemtl glass\nf 1//1 2//1 3//1 4//1\n" // a quad: two triangles
                              "usemtl lamp\nf -4 -3 -2\n"             // negative indices
                              "usemtl filter\nf 1 3 4\n");
    writeFile(dir + "/b.obj", "v 0 0 1\nv 1 0 1\nv 0 1 1\nf 1 2 3\n"); // no material at all
    Scene scene;
    loadObj(dir + "/a.obj", scene);
    loadObj(dir + "/b.obj", scene);
    REQUIRE(scene.triangles.size() == 5);
    const Material glass = materialNamed(scene, "glass");
    CHECK(glass.Kt.g == Approx(0.8f));
    CHECK(glass.Ni == Approx(1.33f));
    CHECK(materialNamed(scene, "filter").Kt.b == Approx(0.5f));
    CHECK(materialNamed(scene, "lamp").Ke.b == Approx(4.0f));
    CHECK(materialNamed(scene, "(default)").Kd.r == Approx(0.5f));
    CHECK(scene.vertexNormals[scene.triangles[0][0]].z == Approx(1.0f));
    CHECK(scene.materialNames[scene.triangleMaterials[2]] == "lamp");
    CHECK(scene.materialNames[scene.triangleMaterials[4]] == "(default)");
}

TEST_CASE("scene scripts: comments, several options per line, paths relative to the script",
          "[scene]") {
    const std::string dir = test::temporaryFolder("ecs");
    std::filesystem::create_directories(dir + "/meshes");
    writeFile(dir + "/meshes/t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    writeFile(dir + "/s.ecs", "# a comment line\n"
                              "-i meshes/t.obj   # trailing comment\n"
                              "-vp 1 2 3 -vi 0 0 0 -vu 0 0 1 -fov 50\n"
                              "--pointlight 0 5 0 10 20 30\n");
    // Options after -c override the script, as on Embree's command line.
    const RenderOptions options = optionsFor({"-c", dir + "/s.ecs", "--fov", "20"});
    REQUIRE(options.objFiles.size() == 1);
    CHECK(std::filesystem::exists(options.objFiles[0]));
    CHECK(options.camera.position.y == Approx(2));
    CHECK(options.camera.up.z == Approx(1));
    CHECK(options.camera.fovDegrees == Approx(20));
    REQUIRE(options.pointLights.size() == 1);
    CHECK(options.pointLights[0].intensity.b == Approx(30));
}
