// A model given without a camera or a light: PathLab frames it from the front and puts a light
// at the camera, each with one note; a scene that has them keeps its own.
#include "catch.h"
#include "test_support.h"

#include "pathlab/scene_io/bounding_box.h"
#include "pathlab/constants.h"
#include "pathlab/images/image_io.h"
#include "pathlab/scene_io/model_coverage.h"
#include "pathlab/render/render_options.h"
#include "pathlab/render/scene_from_options.h"
#include "pathlab/scene_io/scene_defaults.h"

#include <cmath>
#include <fstream>
#include <limits>

using namespace pathlab;

namespace {

void writeFile(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

/// A table on a floor, away from the origin and longer in x than in y: a box of four quads (its
/// top and sides) on a floor quad, no material (grey), no camera, no light.
std::string tableWithoutCameraOrLight() {
    const std::string path = test::temporaryFolder("defaults") + "/table.obj";
    writeFile(path, "v 2 -1 3\nv 10 -1 3\nv 10 -1 9\nv 2 -1 9\n" // the floor
                    "v 4 -1 5\nv 8 -1 5\nv 8 1 5\nv 4 1 5\n"     // the front
                    "v 4 1 7\nv 8 1 7\n"                         // the top's back
                    "f 1 4 3 2\nf 5 6 7 8\nf 8 7 10 9\nf 6 10 7\nf 5 8 9\n");
    return path;
}

RenderOptions optionsFor(const std::vector<std::string>& arguments) {
    std::vector<const char*> argv = {"viewer"};
    for (const std::string& a : arguments) argv.push_back(a.c_str());
    return parseRenderOptions(static_cast<int>(argv.size()), argv.data());
}

/// How far out the farthest of `scene`'s triangle vertices projects, as a share of the image's
/// half-extent: at most 1 when every vertex is in view.
float reach(const Scene& scene, const CameraSettings& camera, int width, int height) {
    const Vec3 forward = normalize(camera.lookAt - camera.position);
    const Vec3 right = normalize(cross(forward, camera.up));
    const Vec3 up = cross(right, forward);
    const float halfHeight = std::tan(0.5f * camera.fovDegrees * Pi / 180.0f);
    const float halfWidth = halfHeight * static_cast<float>(width) / static_cast<float>(height);
    float most = 0;
    for (const auto& triangle : scene.triangles) {
        for (const uint32_t v : triangle) {
            const Vec3 d = scene.positions[v] - camera.position;
            const float depth = dot(d, forward);
            if (depth <= 0) return std::numeric_limits<float>::infinity();
            most = std::max({most, std::abs(dot(d, right) / depth) / halfWidth,
                             std::abs(dot(d, up) / depth) / halfHeight});
        }
    }
    return most;
}

} // namespace

TEST_CASE("a model without a camera is framed whole, from the front, above and to the side",
          "[scene]") {
    const std::string obj = tableWithoutCameraOrLight();
    for (const auto& [width, height] :
         {std::pair{64, 64}, std::pair{160, 90}, std::pair{90, 160}}) {
        const RenderOptions options =
            optionsFor({"-i", obj, "--size", std::to_string(width), std::to_string(height)});
        const Scene scene = loadScene(options);
        REQUIRE(scene.camera.has_value());
        const CameraSettings& camera = *scene.camera;
        INFO(width << "x" << height);
        CHECK(camera.fovDegrees == Approx(45));
        CHECK(camera.up.y == 1);
        // From the +z side, above and to the +x side: framingDirection(), where the table fills
        // enough of the image from there. In a tall image the wide table fills too little of it
        // seen from the front, so the camera looks from where it fills at least 1.5 times as much.
        const Vec3 from = camera.position - camera.lookAt;
        const double share = coveredShare(scene, camera, float(width) / float(height));
        if (width >= height) {
            CHECK(dot(normalize(from), framingDirection()) == Approx(1));
            CHECK(share >= FramingEnoughShare);
        } else {
            CHECK(dot(normalize(from), framingDirection()) < 0.99f);
            GivenCamera fromTheFront;
            fromTheFront.viewDirection = -framingDirection();
            const float aspect = float(width) / float(height);
            const CameraSettings front = framingCamera(scene, fromTheFront, aspect);
            CHECK(coveredShare(scene, front, aspect) < FramingEnoughShare);
            CHECK(share >= FramingBetterBy * coveredShare(scene, front, aspect));
        }
        // Every vertex in view, and one at the margin: not so far back that the model is small.
        CHECK(reach(scene, camera, width, height) == Approx(FramingFill));
    }
}

TEST_CASE("a flat model seen nearly edge-on from the front is framed face-on, not along up",
          "[scene][solutions]") {
    const std::string dir = test::temporaryFolder("defaults-flat");
    const std::string path = dir + "/floor.obj";
    // A floor (y = 0, facing up): from framingDirection() it shows 30% of its area, so the
    // camera looks down on it, leaning to the front.
    writeFile(path, "v -5 0 -5\nv 5 0 -5\nv 5 0 5\nv -5 0 5\nf 1 4 3 2\n");
    const Scene scene = loadScene(optionsFor({"-i", path, "--size", "64", "64"}));
    const Vec3 from = normalize(scene.camera->position - scene.camera->lookAt);
    CHECK(from.y > 0.9f);
    CHECK(from.y < 0.97f);
    CHECK(from.z > 0);
    CHECK(reach(scene, *scene.camera, 64, 64) == Approx(FramingFill));
    // The far corners are in view: the floor fills a good part of the image.
    const std::string image = dir + "/floor.pfm";
    const auto run = test::runViewer(
        "-i " + path + " --size 32 32 --spp 4 --lab importance --solution -o " + image);
    INFO(run.output);
    REQUIRE(run.exitStatus == 0);
    const Image rendered = readImage(image);
    int lit = 0;
    for (size_t i = 0; i < rendered.rgb.size(); i += 3) lit += rendered.rgb[i] > 0;
    CHECK(lit > 32 * 32 / 3);
}

TEST_CASE("--vu and --fov given without a position are kept by the framing camera", "[scene]") {
    const RenderOptions options =
        optionsFor({"-i", tableWithoutCameraOrLight(), "--fov", "30", "--vu", "0", "0", "1"});
    const Scene scene = loadScene(options);
    CHECK(scene.camera->fovDegrees == Approx(30));
    CHECK(scene.camera->up.z == 1);
}

TEST_CASE("--vp alone looks at the model's centre; --vi alone stands back just enough", "[scene]") {
    const std::string obj = tableWithoutCameraOrLight();
    const Scene framed = loadScene(optionsFor({"-i", obj}));
    const BoundingBox box = framed.bounds();

    const Scene positioned = loadScene(optionsFor({"-i", obj, "--vp", "0", "5", "20"}));
    CHECK(positioned.camera->position.z == 20);
    CHECK(positioned.camera->lookAt.x == Approx(box.centre().x));
    CHECK(positioned.camera->lookAt.y == Approx(box.centre().y));
    CHECK(positioned.camera->lookAt.z == Approx(box.centre().z));

    const Scene aimed = loadScene(optionsFor({"-i", obj, "--vi", "4", "0", "5"}));
    CHECK(aimed.camera->lookAt.x == 4);
    const Vec3 back = aimed.camera->position - aimed.camera->lookAt;
    // From the direction a camera placed to look at that point chooses (the front, unless the
    // model fills too little of the image from there).
    CameraSettings toward;
    toward.lookAt = {4, 0, 5};
    toward.fovDegrees = FramingFovDegrees;
    CHECK(dot(normalize(back), framingDirectionFor(aimed, toward, true, 1.0f)) == Approx(1));
    CHECK(reach(aimed, *aimed.camera, 512, 512) == Approx(FramingFill));

    // --vd without --vp looks along it at the model, the whole model in view.
    const Scene along = loadScene(optionsFor({"-i", obj, "--vd", "0", "0", "1"}));
    const Vec3 view = normalize(along.camera->lookAt - along.camera->position);
    CHECK(view.z == Approx(1));
    CHECK(reach(along, *along.camera, 512, 512) == Approx(FramingFill));
}

TEST_CASE("the framing camera and the default light each say so in one note", "[scene]") {
    const std::string image = test::temporaryFolder("defaults-note") + "/out.png";
    const auto run =
        test::runViewer("-i " + tableWithoutCameraOrLight() + " --size 16 16 --spp 1 -o " + image);
    INFO(run.output);
    CHECK(run.exitStatus == 0);
    CHECK(run.output.find("note: no camera given (--vp/--vi): looking at the model (") !=
          std::string::npos);
    CHECK(run.output.find("; set --vp X Y Z --vi X Y Z to choose\n") != std::string::npos);
    CHECK(run.output.find("note: the scene has no light (no Ke material, no --pointlight, no "
                          "--dirlight): added a point light of ") != std::string::npos);
    CHECK(run.output.find(" W/sr at the camera; give --pointlight X Y Z R G B or --dirlight DX "
                          "DY DZ R G B instead\n") != std::string::npos);

    const auto along = test::runViewer("-i " + tableWithoutCameraOrLight() +
                                       " --vd 0 0 1 --size 16 16 --spp 1 -o " + image);
    INFO(along.output);
    CHECK(along.output.find("note: no --vp given: looking along --vd at the model (") !=
          std::string::npos);
    CHECK(along.output.find("no camera given") == std::string::npos);
}

TEST_CASE("the default light is a headlight: a white surface facing it has radiance 1", "[scene]") {
    const Scene scene = loadScene(optionsFor({"-i", tableWithoutCameraOrLight()}));
    REQUIRE(scene.pointLights.size() == 1);
    const PointLight& light = scene.pointLights[0];
    const Vec3 toLookAt = scene.camera->lookAt - scene.camera->position;
    CHECK(light.position.x == scene.camera->position.x);
    CHECK(light.position.z == scene.camera->position.z);
    // E = I/d² = π at the look-at distance d, so Kd/π·E = 1 for Kd 1.
    CHECK(light.intensity.g / dot(toLookAt, toLookAt) == Approx(Pi));
}

TEST_CASE("a scene with a light gets no extra light, and a camera given is kept", "[scene]") {
    const std::string dir = test::temporaryFolder("lit");
    writeFile(dir + "/m.mtl", "newmtl lamp\nKe 1 1 1\n");
    writeFile(dir + "/lamp.obj", "mtllib m.mtl\nusemtl lamp\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const std::string obj = tableWithoutCameraOrLight();
    CHECK(loadScene(optionsFor({"-i", dir + "/lamp.obj"})).pointLights.empty());
    const Scene pointLit =
        loadScene(optionsFor({"-i", obj, "--pointlight", "0", "5", "0", "1", "1", "1", "--vp", "1",
                              "2", "3", "--vi", "0", "0", "0"}));
    CHECK(pointLit.pointLights.size() == 1);
    CHECK(pointLit.camera->position.z == 3);
    CHECK(pointLit.camera->fovDegrees == 90); // as before: a camera given keeps Embree's 90°
    const Scene dirLit =
        loadScene(optionsFor({"-i", obj, "--dirlight", "0", "-1", "0", "1", "1", "1"}));
    CHECK(dirLit.pointLights.empty());
    CHECK(dirLit.directionalLights.size() == 1);

    const std::string image = dir + "/out.png";
    const auto run = test::runViewer("-i " + obj +
                                     " --pointlight 0 5 0 1 1 1 --vp 1 2 3 --vi 0 "
                                     "0 0 --size 8 8 --spp 1 -o " +
                                     image);
    INFO(run.output);
    CHECK(run.exitStatus == 0);
    CHECK(run.output.find("note: no camera") == std::string::npos);
    CHECK(run.output.find("no light") == std::string::npos);
}

TEST_CASE("a model without a camera or a light renders visibly in every lab",
          "[scene][solutions]") {
    const std::string obj = tableWithoutCameraOrLight();
    const std::string dir = test::temporaryFolder("defaults-labs");
    for (Lab lab : AllLabs) {
        const std::string image = dir + "/" + std::string(labName(lab)) + ".pfm";
        const auto run = test::runViewer("-i " + obj + " --size 48 32 --spp 4 --solution --lab " +
                                         std::string(labName(lab)) + " -o " + image);
        INFO(labName(lab) << ": " << run.output);
        REQUIRE(run.exitStatus == 0);
        const Image rendered = readImage(image);
        size_t lit = 0;
        const size_t pixels = rendered.rgb.size() / 3;
        for (size_t p = 0; p < pixels; ++p)
            lit += rendered.rgb[3 * p] + rendered.rgb[3 * p + 1] + rendered.rgb[3 * p + 2] > 0;
        CHECK(double(lit) >= 0.1 * double(pixels));
    }
}

TEST_CASE("the share of the image a model covers: a square seen face-on, from behind, "
          "behind a wall, tiny and behind the camera",
          "[scene]") {
    Scene scene;
    // A square of side 1 at the origin facing +z (counter-clockwise seen from there), seen
    // from distance 1 with a 90° field of view: the image spans [-1, 1] there, so the square
    // covers the middle half of each side, 1/4 (a corner on a pixel edge may mark one pixel
    // more).
    scene.positions = {{-0.5f, -0.5f, 0}, {0.5f, -0.5f, 0}, {0.5f, 0.5f, 0}, {-0.5f, 0.5f, 0}};
    scene.triangles = {{0, 1, 2}, {0, 2, 3}};
    CameraSettings camera;
    camera.position = {0, 0, 1};
    camera.lookAt = {0, 0, 0};
    camera.fovDegrees = 90;
    const double pixel = 1.0 / (48 * 48);
    CHECK(coveredShare(scene, camera, 1.0f) == Approx(0.25).margin(2 * pixel));
    // In an image twice as wide the square covers a quarter of the width, half the height.
    CHECK(coveredShare(scene, camera, 2.0f) == Approx(0.125).margin(4 * pixel));
    // From behind, its back side: nothing counts.
    camera.position = {0, 0, -1};
    CHECK(coveredShare(scene, camera, 1.0f) == Approx(0).margin(2 * pixel));
    // Behind a wall facing away from the camera (a room's wall seen from outside): hidden.
    camera.position = {0, 0, 1};
    scene.positions.insert(scene.positions.end(),
                           {{-1, -1, 0.5f}, {-1, 1, 0.5f}, {1, 1, 0.5f}, {1, -1, 0.5f}});
    scene.triangles.push_back({4, 5, 6});
    scene.triangles.push_back({4, 6, 7});
    CHECK(coveredShare(scene, camera, 1.0f) == Approx(0).margin(2 * pixel));
    // Behind the camera: nothing.
    scene.triangles.resize(2);
    camera.lookAt = {0, 0, 2};
    CHECK(coveredShare(scene, camera, 1.0f) == 0);
    // A triangle far smaller than a pixel marks the one its first vertex falls in.
    scene.positions = {{0.01f, 0.01f, 0}, {0.011f, 0.01f, 0}, {0.01f, 0.011f, 0}};
    scene.triangles = {{0, 1, 2}};
    camera.lookAt = {0, 0, 0};
    CHECK(coveredShare(scene, camera, 1.0f) == Approx(pixel));
}
