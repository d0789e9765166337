// Embree's scene-script options: those PathLab honours (--dirlight, --vd, --lefthanded and
// --righthanded), those it skips with one warning per script, and Embree's XML scenes, refused.
#include "catch.h"
#include "messages.h"
#include "test_support.h"

#include "pathlab/constants.h"
#include "pathlab/render/render_options.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace pathlab;

namespace {

void writeFile(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

RenderOptions optionsFor(const std::vector<std::string>& arguments) {
    std::vector<const char*> argv = {"viewer"};
    for (const std::string& a : arguments) argv.push_back(a.c_str());
    return parseRenderOptions(static_cast<int>(argv.size()), argv.data());
}

std::vector<std::string> words(const std::string& text) {
    std::istringstream in(text);
    std::vector<std::string> out;
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

/// `first`, then the words of `options`: arguments with a path that may hold spaces.
std::vector<std::string> wordsAfter(std::vector<std::string> first, const std::string& options) {
    for (const std::string& w : words(options)) first.push_back(w);
    return first;
}

/// A wall facing the camera on the +x side: what a camera at -z looking at the origin sees on
/// its left when right-handed (Embree's default), with nothing on its right.
std::string wallOnPlusX(const std::string& dir) {
    const std::string path = dir + "/wall.obj";
    writeFile(path, "v 0.5 0 -0.5\nv 1.8 0 -0.5\nv 1.8 1.2 -0.5\nv 0.5 1.2 -0.5\nf 4 3 2 1\n");
    return path;
}

/// The image's left half's mean minus its right half's.
double leftMinusRight(const std::vector<double>& luminance, int width, int height) {
    double left = 0, right = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            (x < width / 2 ? left : right) += luminance[size_t(y) * size_t(width) + size_t(x)];
    return (left - right) / (0.5 * width * height);
}

std::vector<double> luminanceOf(const AccumulationBuffer& image) {
    std::vector<double> out;
    for (int p = 0; p < image.width() * image.height(); ++p) out.push_back(average(image.mean(p)));
    return out;
}

/// A binary PPM (P6, maxval 255) as Embree's pathtracer writes it, summed over the channels.
std::vector<double> readPpm(const std::string& path, int& width, int& height) {
    std::ifstream in(path, std::ios::binary);
    std::string magic;
    int maxValue = 0;
    in >> magic >> width >> height >> maxValue;
    in.get();
    std::vector<double> out;
    for (int i = 0; i < width * height; ++i) {
        unsigned char rgb[3] = {};
        in.read(reinterpret_cast<char*>(rgb), 3);
        out.push_back(rgb[0] + rgb[1] + rgb[2]);
    }
    return out;
}

} // namespace

TEST_CASE("Embree's options PathLab has no meaning for skip their values", "[scene]") {
    // Each followed by --seed 3, which must still read as an option.
    for (const char* ignored : {"--shader uv",
                                "--shader cycles 2.5",
                                "--compare ref.png",
                                "--compare-threshold 700",
                                "--time 0.5",
                                "--rtcore verbose=2",
                                "--isa avx2",
                                "--verbose 2",
                                "--ambientlight 1 1 1",
                                "-ambient 1 1 1",
                                "--distantlight 0 -1 0 1 1 1 0.1",
                                "--fullscreen",
                                "--print-frame-rate",
                                "--print-camera",
                                "--coherent",
                                "--incoherent",
                                "--debug0 1",
                                "--debug3 4",
                                "--animation",
                                "--instancing geometry",
                                "--convert-triangles-to-quads",
                                "--convert-bezier-to-lines",
                                "--grid-res 4 4",
                                "--remove-mblur",
                                "--remove-non-mblur",
                                "--merge-quads-to-grids",
                                "--merge-triangles-to-grids",
                                "--camera main",
                                "--print-cameras",
                                "--accumulate 1",
                                "--max-path-length 8",
                                "--sphere 0 0 0 1",
                                "--triangle-sphere 0 0 0 1 8",
                                "--quad-plane 0 0 0 1 0 0 0 1 0 4 4",
                                "--point-sphere-mblur 0 0 0 1 0 0 1 0.1 8",
                                "--hair-plane 0 0 0 1 0 0 0 1 0 1 0.1 8"}) {
        std::vector<std::string> arguments = words(ignored);
        arguments.insert(arguments.end(), {"--seed", "3"});
        INFO(ignored);
        CHECK(optionsFor(arguments).seed == 3);
    }
}

TEST_CASE("ignored Embree options are named in one warning per script, with their values",
          "[scene]") {
    const std::string dir = test::temporaryFolder("ecs-ignored");
    writeFile(dir + "/m.mtl", "newmtl white\nKd 0.5 0.5 0.5\n");
    writeFile(dir + "/a.obj", "mtllib m.mtl\nusemtl white\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    writeFile(dir + "/s.ecs", "-i a.obj\n"
                              "--shader uv\n"
                              "-vp 0.3 0.3 -2 -vi 0.3 0.3 0 --pointlight 0 0 -2 1 1 1\n"
                              "--compare-threshold 700\n"
                              "--sphere 0 0 0 1 --max-path-length 4\n");
    const auto run = test::runViewer("-c " + dir + "/s.ecs --size 8 8 --spp 1 --print-camera -o " +
                                     dir + "/out.png");
    INFO(run.output);
    CHECK(run.exitStatus == 0);
    CHECK(run.output.find("warning: " + dir +
                          "/s.ecs:2: ignored Embree options PathLab has no meaning for: --shader "
                          "uv, --compare-threshold 700, --sphere 0 0 0 1 (PathLab does not "
                          "generate geometry), --max-path-length 4 (PathLab's depth is "
                          "--max-depth)\n") != std::string::npos);
    // The command line's own, after the script's.
    CHECK(run.output.find("warning: ignored Embree options PathLab has no meaning for: "
                          "--print-camera\n") != std::string::npos);
}

TEST_CASE("a script's ignored option short of its values is an error on its line", "[scene]") {
    const std::string dir = test::temporaryFolder("ecs-short");
    writeFile(dir + "/s.ecs", "--ambientlight 1 1\n--fov 30\n");
    CHECK(contains(messageOf<std::exception>([&] {
                       optionsFor({"-c", dir + "/s.ecs"});
                   }),
                   "s.ecs:1: option --ambientlight needs a value"));
}

TEST_CASE("--dirlight, -dirlight and --directionallight add a directional light", "[scene]") {
    for (const char* spelling : {"--dirlight", "-dirlight", "--directionallight"}) {
        const RenderOptions options = optionsFor({spelling, "-1", "-1", "1", "3", "2", "1"});
        REQUIRE(options.directionalLights.size() == 1);
        CHECK(options.directionalLights[0].direction.z == 1);
        CHECK(options.directionalLights[0].irradiance.g == 2);
    }
    CHECK(contains(messageOf<std::exception>([] {
                       optionsFor({"--dirlight", "0", "0", "0", "1", "1", "1"});
                   }),
                   "expects a direction"));
    CHECK(contains(messageOf<std::exception>([] {
                       optionsFor({"--dirlight", "0", "-1", "0", "-1", "1", "1"});
                   }),
                   "cannot be negative"));
}

// A large diffuse plane of albedo a facing a directional light of irradiance E along its
// normal: with nothing to bounce to, every lab's every sample is the direct light a·E/π, up to
// rounding. The estimate has no variance (one light, picked with probability 1; a plane that
// sees nothing else), so the tolerance is rounding's and the test cannot fail by chance.
TEST_CASE("a directional light's furnace: a plane facing it has radiance a·E/π in every lab",
          "[scene][solutions]") {
    const std::string dir = test::temporaryFolder("dirlight-furnace");
    writeFile(dir + "/m.mtl", "newmtl plane\nKd 0.6 0.5 0.4\n");
    writeFile(dir + "/plane.obj", "mtllib m.mtl\nusemtl plane\n"
                                  "v -100 0 -100\nv 100 0 -100\nv 100 0 100\nv -100 0 100\n"
                                  "f 1 4 3 2\n");
    const Color albedo{0.6f, 0.5f, 0.4f};
    const Color irradiance{2.0f, 3.0f, 4.0f};
    for (Lab lab : AllLabs)
        for (const auto& [dx, dz] : {std::pair{"0", "0"}, std::pair{"0.3", "0.2"}}) {
            std::vector<std::string> arguments = wordsAfter(
                {"-i", dir + "/plane.obj", "--lab", std::string(labName(lab))},
                "--vp 0 10 0 --vi 0 0 0 --vu 0 0 1 --size 32 32 --spp 4 --seed 7 --solution");
            arguments.insert(arguments.end(), {"--dirlight", dx, "-1", dz, "2", "3", "4"});
            if (lab != Lab::Roulette) arguments.insert(arguments.end(), {"--max-depth", "0"});
            const HeadlessResult result = test::render(arguments);
            // Along the normal, or at an angle: cosθ = 1/|(dx, -1, dz)|.
            const float x = std::stof(dx), z = std::stof(dz);
            const float cosine = 1.0f / std::sqrt(x * x + 1.0f + z * z);
            Color sum;
            int pixels = 0;
            for (int y = 8; y < 24; ++y)
                for (int x = 8; x < 24; ++x, ++pixels) sum += result.image.mean(y * 32 + x);
            const Color mean = sum / static_cast<float>(pixels);
            INFO(labName(lab) << ", light along (" << dx << ", -1, " << dz << ")");
            CHECK(mean.r == Approx(albedo.r * irradiance.r * cosine * InvPi).epsilon(1e-4));
            CHECK(mean.g == Approx(albedo.g * irradiance.g * cosine * InvPi).epsilon(1e-4));
            CHECK(mean.b == Approx(albedo.b * irradiance.b * cosine * InvPi).epsilon(1e-4));
        }
}

TEST_CASE("a directional light casts shadows", "[scene][solutions]") {
    const std::string dir = test::temporaryFolder("dirlight-shadow");
    // A floor and, above its -x half, a roof: light straight down reaches only the +x half.
    writeFile(dir + "/s.obj", "v -4 0 -4\nv 4 0 -4\nv 4 0 4\nv -4 0 4\n"
                              "v -8 1 -8\nv 0 1 -8\nv 0 1 8\nv -8 1 8\n"
                              "f 1 4 3 2\nf 5 8 7 6\n");
    // Seen from straight above the floor's centre, under the roof's edge at x = 0: the +x half
    // (on the image's left, right-handed) is lit, Kd/π·E with the default Kd 0.5; the -x half
    // under the roof is black.
    const HeadlessResult above = test::render(
        wordsAfter({"-i", dir + "/s.obj"},
                   "--dirlight 0 -1 0 1 1 1 --vp 0 0.9 0 --vi 0 0 0 --vu 0 0 1 --fov 60 --size 16 "
                   "16 --spp 1 --solution --lab importance --max-depth 0"));
    CHECK(average(above.image.mean(8 * 16 + 2)) == Approx(InvPi * 0.5f).epsilon(1e-4));
    CHECK(average(above.image.mean(8 * 16 + 13)) == 0);
}

TEST_CASE("--vd looks at --vp + direction: the same image as --vi there, bit for bit",
          "[scene][solutions]") {
    const std::vector<std::string> common =
        wordsAfter({"-c", test::modelPath("cornell_box_diffuse.ecs")},
                   "--size 24 24 --spp 2 --solution --lab importance --vp 278 273 -700");
    std::vector<std::string> withVd = common, withVi = common;
    withVd.insert(withVd.end(), {"--vd", "-28", "-23", "700"});
    withVi.insert(withVi.end(), {"--vi", "250", "250", "0"});
    CHECK(optionsFor(withVd).camera.lookAt.x == 250);
    const HeadlessResult a = test::render(withVd), b = test::render(withVi);
    CHECK(a.image.meanImage() == b.image.meanImage());
    // Given before --vp, as Embree's scripts never do, it still adds to the final position.
    const RenderOptions vdFirst =
        optionsFor({"--vd", "-28", "-23", "700", "--vp", "278", "273", "-700"});
    CHECK(vdFirst.camera.lookAt.x == 250);
    CHECK(vdFirst.cameraLookAtSet);
}

TEST_CASE("--righthanded is Embree's default and PathLab's; --lefthanded mirrors the image",
          "[scene][solutions]") {
    const std::string dir = test::temporaryFolder("handedness");
    const std::vector<std::string> common =
        wordsAfter({"-i", wallOnPlusX(dir)}, "--vp 0 1 -5 --vi 0 0.5 0 --fov 40 --pointlight 0 3 "
                                             "-3 20 20 20 --size 32 32 --spp 8 --solution --lab "
                                             "importance");
    std::vector<std::string> right = common, left = common;
    right.push_back("--righthanded");
    left.push_back("--lefthanded");
    const HeadlessResult plain = test::render(common);
    const HeadlessResult rightHanded = test::render(right);
    const HeadlessResult leftHanded = test::render(left);
    CHECK(plain.image.meanImage() == rightHanded.image.meanImage());
    const double plainSide = leftMinusRight(luminanceOf(plain.image), 32, 32);
    const double leftSide = leftMinusRight(luminanceOf(leftHanded.image), 32, 32);
    // The wall at +x: on the left of a right-handed image, on the right of a left-handed one.
    CHECK(plainSide > 0.02);
    CHECK(leftSide < -0.02);
    // The same pixels mirrored, up to noise (the mirrored pixel's samples differ).
    const std::vector<double> a = luminanceOf(plain.image), b = luminanceOf(leftHanded.image);
    double mirrored = 0, unmirrored = 0;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) {
            mirrored += std::abs(a[size_t(y * 32 + x)] - b[size_t(y * 32 + 31 - x)]);
            unmirrored += std::abs(a[size_t(y * 32 + x)] - b[size_t(y * 32 + x)]);
        }
    CHECK(mirrored < 0.5 * unmirrored);
}

TEST_CASE("handedness agrees with Embree's own pathtracer on the same OBJ", "[scene][solutions]") {
    if (std::system("command -v pathtracer > /dev/null 2>&1") != 0)
        PATHLAB_SKIP("Embree's pathtracer (embree-tools) is not installed");
    const std::string dir = test::temporaryFolder("handedness-embree");
    const std::string obj = wallOnPlusX(dir);
    for (const char* handedness : {"", "--righthanded", "--lefthanded"}) {
        const std::string camera = std::string("--vp 0 1 -5 --vi 0 0.5 0 --fov 40 --pointlight 0 "
                                               "3 -3 20 20 20 --size 32 32 ") +
                                   handedness;
        const std::string ppm = dir + "/embree.ppm";
        REQUIRE(std::system(("pathtracer -i " + obj + " " + camera + " --spp 8 -o " + ppm +
                             " > /dev/null 2>&1")
                                .c_str()) == 0);
        int width = 0, height = 0;
        const std::vector<double> embree = readPpm(ppm, width, height);
        REQUIRE(width == 32);
        std::vector<std::string> arguments = {"-i", obj, "--spp", "8", "--solution"};
        const std::vector<std::string> cameraWords = words(camera);
        arguments.insert(arguments.end(), cameraWords.begin(), cameraWords.end());
        const HeadlessResult ours = test::render(arguments);
        INFO("handedness '" << handedness << "'");
        const double embreeSide = leftMinusRight(embree, 32, 32);
        const double ourSide = leftMinusRight(luminanceOf(ours.image), 32, 32);
        CHECK(embreeSide * ourSide > 0);
    }
}

TEST_CASE("Embree's XML scenes are refused in one line, by name or by their first bytes",
          "[scene]") {
    const std::string dir = test::temporaryFolder("xml");
    writeFile(dir + "/box.xml", "<?xml version=\"1.0\"?>\n<scene>\n</scene>\n");
    writeFile(dir + "/disguised.obj", "\n  <scene>\n  <TriangleMesh/>\n</scene>\n");
    for (const std::string& file : {dir + "/box.xml", dir + "/disguised.obj"}) {
        const auto run = test::runViewer("-i " + file + " -o " + dir + "/out.png");
        INFO(run.output);
        CHECK(run.exitStatus == 2);
        CHECK(run.output.find(file + ": an Embree XML scene; PathLab reads OBJ (-i FILE.obj) and "
                                     "Embree's .ecs scripts that name OBJ files, not Embree's XML "
                                     "format\n") != std::string::npos);
        CHECK(std::count(run.output.begin(), run.output.end(), '\n') == 1);
        CHECK(!std::filesystem::exists(dir + "/out.png"));
    }
    // Named by a script, as Embree's own cornell_box_instanced.ecs names its .xml.
    writeFile(dir + "/s.ecs", "-i box.xml\n");
    const auto run = test::runViewer("-c " + dir + "/s.ecs -o " + dir + "/out.png");
    CHECK(run.exitStatus == 2);
    CHECK(run.output.find("box.xml: an Embree XML scene") != std::string::npos);
}
