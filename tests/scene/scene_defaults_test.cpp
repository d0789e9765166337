// A model given without a camera or a light: PathLab frames it from the front and puts a light
// at the camera, each with one note; a scene that has them keeps its own.
#include "catch.h"
#include "test_support.h"

#include "pathlab/bounding_box.h"
#include "pathlab/constants.h"
#include "pathlab/image_io.h"
#include "pathlab/render_options.h"
#include "pathlab/scene_defaults.h"

#include <cmath>
#include <fstream>

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

/// Whether `point` projects inside the image of a camera of `width` x `height` pixels, in front
/// of it: the same frame as pathlab::Camera's.
bool inView(const CameraSettings& camera, int width, int height, const Vec3& point) {
    const Vec3 forward = normalize(camera.lookAt - camera.position);
    const Vec3 right = normalize(cross(forward, camera.up));
    const Vec3 up = cross(right, forward);
    const Vec3 d = point - camera.position;
    const float depth = dot(d, forward);
    const float halfHeight = std::tan(0.5f * camera.fovDegrees * Pi / 180.0f);
    const float halfWidth = halfHeight * static_cast<float>(width) / static_cast<float>(height);
    return depth > 0 && std::abs(dot(d, right) / depth) <= halfWidth &&
           std::abs(dot(d, up) / depth) <= halfHeight;
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
        const BoundingBox box = boundingBoxOf(scene.positions);
        INFO(width << "x" << height);
        CHECK(camera.lookAt.x == Approx(box.centre().x));
        CHECK(camera.lookAt.y == Approx(box.centre().y));
        CHECK(camera.lookAt.z == Approx(box.centre().z));
        CHECK(camera.fovDegrees == Approx(45));
        CHECK(camera.up.y == 1);
        // From the +z side, above and to the +x side.
        const Vec3 from = camera.position - camera.lookAt;
        CHECK(from.z > 0);
        CHECK(from.y > 0);
        CHECK(from.x > 0);
        for (int corner = 0; corner < 8; ++corner) {
            const Vec3 p{corner & 1 ? box.hi.x : box.lo.x, corner & 2 ? box.hi.y : box.lo.y,
                         corner & 4 ? box.hi.z : box.lo.z};
            CHECK(inView(camera, width, height, p));
        }
        // Not so far that the model is small: the sphere around it touches the narrower side.
        const float distance = length(from);
        const float halfV = 0.5f * 45.0f * Pi / 180.0f;
        const float halfH = std::atan(std::tan(halfV) * float(width) / float(height));
        CHECK(distance == Approx(box.radius() / std::sin(std::min(halfV, halfH))));
    }
}

TEST_CASE("--vu and --fov given without a position are kept by the framing camera", "[scene]") {
    const RenderOptions options =
        optionsFor({"-i", tableWithoutCameraOrLight(), "--fov", "30", "--vu", "0", "0", "1"});
    const Scene scene = loadScene(options);
    CHECK(scene.camera->fovDegrees == Approx(30));
    CHECK(scene.camera->up.z == 1);
}

TEST_CASE("--vp alone looks at the model's centre; --vi alone stands the framing distance back",
          "[scene]") {
    const std::string obj = tableWithoutCameraOrLight();
    const Scene framed = loadScene(optionsFor({"-i", obj}));
    const float framingDistance = length(framed.camera->position - framed.camera->lookAt);
    const BoundingBox box = boundingBoxOf(framed.positions);

    const Scene positioned = loadScene(optionsFor({"-i", obj, "--vp", "0", "5", "20"}));
    CHECK(positioned.camera->position.z == 20);
    CHECK(positioned.camera->lookAt.x == Approx(box.centre().x));
    CHECK(positioned.camera->lookAt.y == Approx(box.centre().y));
    CHECK(positioned.camera->lookAt.z == Approx(box.centre().z));

    const Scene aimed = loadScene(optionsFor({"-i", obj, "--vi", "4", "0", "5"}));
    CHECK(aimed.camera->lookAt.x == 4);
    const Vec3 back = aimed.camera->position - aimed.camera->lookAt;
    CHECK(length(back) == Approx(framingDistance));
    const Vec3 expected = framingDirection();
    CHECK(dot(normalize(back), expected) == Approx(1));

    // --vd without --vp looks along it at the model.
    const Scene along = loadScene(optionsFor({"-i", obj, "--vd", "0", "0", "1"}));
    CHECK(along.camera->lookAt.z == Approx(box.centre().z));
    CHECK(along.camera->position.z == Approx(box.centre().z - framingDistance));
}

TEST_CASE("the framing camera and the default light each say so in one note", "[scene]") {
    const std::string image = test::temporaryFolder("defaults-note") + "/out.png";
    const auto run =
        test::runViewer("-i " + tableWithoutCameraOrLight() + " --size 16 16 --spp 1 -o " + image);
    INFO(run.output);
    CHECK(run.exitStatus == 0);
    CHECK(run.output.find("note: no camera given (--vp/--vi): looking at the model's centre (6, "
                          "0, 6) from (") != std::string::npos);
    CHECK(run.output.find("; set --vp X Y Z --vi X Y Z to choose\n") != std::string::npos);
    CHECK(run.output.find("note: the scene has no light (no Ke material, no --pointlight, no "
                          "--dirlight): added a point light of ") != std::string::npos);
    CHECK(run.output.find(" W/sr at the camera; give --pointlight X Y Z R G B or --dirlight DX "
                          "DY DZ R G B instead\n") != std::string::npos);
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
