// OBJ and MTL files read as leniently as tinyobjloader reads them: what Blender, MeshLab and
// assimp read with a warning renders, with one warning or note naming file:line and what PathLab
// then assumes; what would make a wrong mesh stays an error of one line and exit status 2.
// Every render here gives its camera (--vp/--vi) and light (--pointlight).
#include "catch.h"
#include "test_support.h"

#include "pathlab/images/image_io.h"
#include "pathlab/scene_io/obj_loader.h"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <utility>
#include <vector>

using namespace pathlab;

namespace {

void writeFile(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

const char* triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

struct Rendered {
    int exitStatus = -1;
    std::string output;
    Image image;
};

/// Renders DIR/FILE (an .obj, or an .ecs with -c) through the reference solution of lab 3, the
/// camera facing the triangle of `triangle` and a light beside the camera.
Rendered render(const std::string& dir, const std::string& file = "a.obj") {
    const std::string scene = (file.size() > 4 && file.substr(file.size() - 4) == ".ecs")
                                  ? "-c " + dir + "/" + file
                                  : "-i " + dir + "/" + file;
    const std::string image = dir + "/out.pfm";
    Rendered r;
    const auto run = test::runViewer(scene +
                                     " --size 16 16 --spp 4 --lab importance --solution"
                                     " --vp 0.3 0.3 -2 --vi 0.3 0.3 0"
                                     " --pointlight 0.3 0.3 -1 1 1 1 -o " +
                                     image);
    r.exitStatus = run.exitStatus;
    r.output = run.output;
    if (r.exitStatus == 0) r.image = readImage(image);
    return r;
}

/// The brightest pixel's value in channel `c` (0 red, 1 green, 2 blue).
float brightest(const Image& image, int c) {
    float most = 0;
    for (size_t i = static_cast<size_t>(c); i < image.rgb.size(); i += 3)
        most = std::max(most, image.rgb[i]);
    return most;
}

bool has(const std::string& output, const std::string& text) {
    return output.find(text) != std::string::npos;
}

size_t lines(const std::string& output, const std::string& start) {
    size_t n = 0;
    std::istringstream in(output);
    for (std::string line; std::getline(in, line);) n += line.rfind(start, 0) == 0;
    return n;
}

/// Expects the render to succeed with a lit, grey (Kd 0.5) triangle in the image.
void expectGreyImage(const Rendered& r) {
    REQUIRE(r.exitStatus == 0);
    CHECK(brightest(r.image, 0) > 0);
    CHECK(brightest(r.image, 0) == Approx(brightest(r.image, 2)));
}

/// A line count of Messages that is not checked.
constexpr int Uncounted = -1;

/// What a render's output says: each of `says` somewhere in it and, unless Uncounted, how many of
/// its lines are warnings and how many notes.
struct Messages {
    std::vector<std::string> says;
    int warnings = Uncounted;
    int notes = Uncounted;
};

/// Expects the output to say what `expected` lists, a check for each text and each count.
void expectMessages(const std::string& output, const Messages& expected) {
    for (const std::string& text : expected.says) {
        INFO("expected to say: " << text);
        CHECK(has(output, text));
    }
    if (expected.warnings != Uncounted)
        CHECK(lines(output, "warning:") == static_cast<size_t>(expected.warnings));
    if (expected.notes != Uncounted)
        CHECK(lines(output, "note:") == static_cast<size_t>(expected.notes));
}

/// Renders DIR/FILE and expects the lit grey triangle (expectGreyImage) and the output to say
/// `expected`; returns the render for further checks.
Rendered renderGrey(const std::string& dir, const Messages& expected,
                    const std::string& file = "a.obj") {
    const Rendered r = render(dir, file);
    INFO(r.output);
    expectGreyImage(r);
    expectMessages(r.output, expected);
    return r;
}

/// Renders DIR/a.obj and expects it to succeed with the triangle lit in channel `lit` (0 red,
/// 1 green, 2 blue) and the output to say `expected`; returns the render for further checks.
Rendered renderLit(const std::string& dir, int lit, const Messages& expected) {
    const Rendered r = render(dir);
    INFO(r.output);
    REQUIRE(r.exitStatus == 0);
    CHECK(brightest(r.image, lit) > 0);
    expectMessages(r.output, expected);
    return r;
}

/// The scene of the OBJ file at `path`, loaded as the viewer loads it.
Scene loadedObj(const std::string& path) {
    Scene scene;
    loadObj(path, scene);
    return scene;
}

Material materialNamed(const Scene& scene, const std::string& name) {
    for (size_t i = 0; i < scene.materials.size(); ++i)
        if (scene.materialNames[i] == name) return scene.materials[i];
    FAIL("no material '" << name << "'");
    throw;
}

std::string materialOfTriangle(const Scene& scene, size_t t) {
    return scene.materialNames[scene.triangleMaterials.at(t)];
}

/// Runs the viewer on DIR/a.obj and expects exit status 2 and one line holding `expected`.
void expectRejected(const std::string& dir, const std::string& expected,
                    const std::string& file = "a.obj") {
    const Rendered r = render(dir, file);
    INFO("output: " << r.output);
    CHECK(r.exitStatus == 2);
    CHECK(has(r.output, expected));
    CHECK(std::count(r.output.begin(), r.output.end(), '\n') == 1);
}

} // namespace

TEST_CASE("a usemtl naming a material no mtllib defines: grey, one warning per file",
          "[scene][obj-leniency][solutions]") {
    const std::string dir = test::temporaryFolder("undefined-material");
    writeFile(dir + "/m.mtl", "newmtl white\nKd 0.5 0.5 0.5\n");
    std::string obj = std::string("mtllib m.mtl\n") + triangle + "usemtl chrome\nf 1 2 3\n";
    for (int i = 0; i < 499; ++i) obj += "usemtl chrome" + std::to_string(i) + "\nf 1 2 3\n";
    writeFile(dir + "/a.obj", obj);
    renderGrey(dir, {{"warning: " + dir +
                      "/a.obj:5: material 'chrome' is not defined by any mtllib: its faces are "
                      "grey (Kd 0.5) (and 499 more like it)"},
                     /*warnings*/ 1,
                     /*notes*/ 0});
}

TEST_CASE("material names with spaces: the whole rest of the line, in newmtl and usemtl alike",
          "[scene][obj-leniency][solutions]") {
    const std::string dir = test::temporaryFolder("spaces");
    writeFile(dir + "/m.mtl",
              "newmtl my red paint\nKd 1 0 0\nnewmtl my   blue\t paint  \nKd 0 0 1\n");
    // The blue triangle hides behind the red one.
    writeFile(dir + "/a.obj", std::string("mtllib m.mtl\n") + triangle +
                                  "v 0 0 1\nv 1 0 1\nv 0 1 1\n"
                                  "usemtl  my red paint \nf 1 2 3\n"
                                  "usemtl my   blue\t paint\nf 4 5 6\n");
    const Rendered r =
        renderLit(dir, /*red*/ 0,
                  {{"note: " + dir +
                    "/m.mtl:1: material name 'my red paint' has spaces: PathLab reads the whole "
                    "rest of the line as the name, in 'newmtl' and 'usemtl' alike"},
                   /*warnings*/ 0,
                   /*notes*/ 1});
    CHECK(brightest(r.image, 1) == 0); // no green: the image is the red triangle's alone

    const Scene scene = loadedObj(dir + "/a.obj");
    REQUIRE(scene.triangles.size() == 2);
    CHECK(materialOfTriangle(scene, 0) == "my red paint");
    CHECK(materialOfTriangle(scene, 1) == "my   blue\t paint");
    CHECK(materialNamed(scene, "my   blue\t paint").Kd.b == 1.0f);
}

TEST_CASE("a newmtl without a name makes a material named '', with a warning",
          "[scene][obj-leniency][solutions]") {
    const std::string dir = test::temporaryFolder("empty-newmtl");
    writeFile(dir + "/m.mtl", "newmtl red\nKd 1 0 0\nnewmtl \nKd 0 0 1\n");
    writeFile(dir + "/a.obj", std::string("mtllib m.mtl\n") + triangle + "usemtl\nf 1 2 3\n");
    const Rendered r = renderLit(
        dir, /*blue*/ 2,
        {{"warning: " + dir + "/m.mtl:3: 'newmtl' without a name: PathLab names the material ''"},
         /*warnings*/ 1});
    CHECK(brightest(r.image, 0) == 0); // no red: the triangle's material is the nameless one

    const Scene scene = loadedObj(dir + "/a.obj");
    CHECK(materialNamed(scene, "red").Kd.r == 1.0f); // not overwritten by the nameless one's Kd
    CHECK(materialNamed(scene, "").Kd.b == 1.0f);
    CHECK(materialOfTriangle(scene, 0).empty());
}

TEST_CASE("an mtllib after the faces is read; a material used before it is grey",
          "[scene][obj-leniency][solutions]") {
    const std::string dir = test::temporaryFolder("late-mtllib");
    writeFile(dir + "/m.mtl", "newmtl red\nKd 1 0 0\n");
    writeFile(dir + "/a.obj", std::string(triangle) + "g first\nusemtl red\nf 1 2 3\n" +
                                  "mtllib m.mtl\ng second\nusemtl red\nf 1 3 2\n");
    renderLit(dir, /*red*/ 0,
              {{"warning: " + dir +
                "/a.obj:5: material 'red' is used before the 'mtllib' that defines it (line 7): "
                "its faces are grey (Kd 0.5), as tinyobjloader reads them"},
               /*warnings*/ 1,
               /*notes*/ 0});

    const Scene scene = loadedObj(dir + "/a.obj");
    REQUIRE(scene.triangles.size() == 2);
    CHECK(materialOfTriangle(scene, 0) == "(default)");
    CHECK(materialOfTriangle(scene, 1) == "red");
}

TEST_CASE("an mtllib whose file is missing: a warning, its materials grey",
          "[scene][obj-leniency][solutions]") {
    const std::string dir = test::temporaryFolder("missing-mtllib");
    writeFile(dir + "/a.obj",
              std::string("mtllib nowhere.mtl\n") + triangle + "usemtl white\nf 1 2 3\n");
    renderGrey(dir, {{"warning: " + dir +
                          "/a.obj:1: material library 'nowhere.mtl' not found: faces of its "
                          "materials are grey (Kd 0.5)",
                      "warning: " + dir + "/a.obj:5: material 'white' is not defined"},
                     /*warnings*/ Uncounted,
                     /*notes*/ 0});
}

TEST_CASE("an Ni of 0, negative, absurd or missing: a warning, PathLab uses 1",
          "[scene][obj-leniency][solutions]") {
    const std::string dir = test::temporaryFolder("ni");
    writeFile(dir + "/m.mtl", "newmtl zero\nKt 1 1 1\nNi 0\n"
                              "newmtl negative\nKt 1 1 1\nNi -1.5\n"
                              "newmtl absurd\nKt 1 1 1\nNi 1000\n"
                              "newmtl missing\nKt 1 1 1\nNi\n"
                              "newmtl glass\nKt 1 1 1\nNi 1.5\n");
    writeFile(dir + "/a.obj", std::string("mtllib m.mtl\n") + triangle + "f 1 2 3\n");
    const Scene scene = loadedObj(dir + "/a.obj");
    for (const char* name : {"zero", "negative", "absurd", "missing"})
        CHECK(materialNamed(scene, name).Ni == 1.0f);
    CHECK(materialNamed(scene, "glass").Ni == 1.5f);

    renderGrey(dir,
               {{"warning: " + dir +
                     "/m.mtl:3: 'Ni' (index of refraction) 0 must be > 0: PathLab uses 1 "
                     "(tinyobjloader's default) (and 2 more like it)",
                 "warning: " + dir + "/m.mtl:12: 'Ni' expects 1 number, found 0: PathLab uses 1"}});
}

TEST_CASE("a colour of one number is grey, as the MTL format says; other odd colours warn",
          "[scene][obj-leniency][solutions]") {
    const std::string dir = test::temporaryFolder("kd");
    writeFile(dir + "/m.mtl", "Kd 1 1 1\n"
                              "newmtl grey\nKd 0.5\n"
                              "newmtl tail\nKd 0.5 0.25x 0.5\n"
                              "newmtl negative\nKd -1 0.25 0\n");
    writeFile(dir + "/a.obj", std::string("mtllib m.mtl\n") + triangle + "usemtl grey\nf 1 2 3\n");
    renderGrey(dir,
               {{"note: " + dir +
                     "/m.mtl:3: 'Kd 0.5' has one number: PathLab reads it as grey (0.5 0.5 "
                     "0.5), as the MTL format says",
                 "warning: " + dir + "/m.mtl:1: 'Kd' comes before any 'newmtl': ignored",
                 "warning: " + dir +
                     "/m.mtl:5: 'Kd' number '0.25x' is read as 0.25, as tinyobjloader "
                     "reads it",
                 "warning: " + dir + "/m.mtl:7: 'Kd' cannot be negative: PathLab reads -1 as 0"}});

    const Scene scene = loadedObj(dir + "/a.obj");
    const Material grey = materialNamed(scene, "grey");
    CHECK(grey.Kd.r == 0.5f);
    CHECK(grey.Kd.g == 0.5f);
    CHECK(grey.Kd.b == 0.5f);
    CHECK(materialNamed(scene, "tail").Kd.g == 0.25f);
    CHECK(materialNamed(scene, "tail").Kd.b == 0.5f);
    CHECK(materialNamed(scene, "negative").Kd.r == 0.0f);
    CHECK(materialNamed(scene, "negative").Kd.g == 0.25f);
}

TEST_CASE("a Tf on a material that says it is opaque (d 1, Tr 0) is no transmission",
          "[scene][obj-leniency]") {
    const std::string dir = test::temporaryFolder("tf");
    // As exporters write an opaque material; the d comes before or after the Tf.
    writeFile(dir + "/m.mtl", "newmtl opaque\nKd 0.6 0.1 0.1\nTf 1 1 1\nd 1\n"
                              "newmtl alsoOpaque\nTr 0\nTf 1 1 1\n"
                              "newmtl clear\nTf 0.5 0.5 0.5\nd 0.5\n"
                              "newmtl filter\nTf 0.25 0.25 0.25\n");
    writeFile(dir + "/a.obj",
              std::string("mtllib m.mtl\n") + triangle + "usemtl opaque\nf 1 2 3\n");
    const auto run =
        test::runViewer("-i " + dir + "/a.obj --size 8 8 --spp 1 -o " + dir + "/out.png");
    INFO(run.output);
    CHECK(run.exitStatus == 0);
    CHECK(has(run.output,
              "warning: " + dir +
                  "/m.mtl:3: 'Tf' on a material that says it is opaque ('d 1' or "
                  "'Tr 0'): PathLab ignores it (read as transmission, 'Tf 1 1 1' would make "
                  "the material clear glass) (and 1 more like it)"));
    CHECK(!has(run.output, "energy conserving"));

    // Each material's transmission (Kt, red channel): none where it says it is opaque.
    const Scene scene = loadedObj(dir + "/a.obj");
    const std::pair<const char*, float> transmissions[] = {
        {"opaque", 0.0f}, {"alsoOpaque", 0.0f}, {"clear", 0.5f}, {"filter", 0.25f}};
    for (const auto& [name, kt] : transmissions) {
        INFO("material " << name);
        CHECK(materialNamed(scene, name).Kt.r == kt);
    }
}

TEST_CASE("a colour or Ni that is no number at all is an error naming its line",
          "[scene][obj-leniency][bad-input]") {
    const std::string dir = test::temporaryFolder("kd-error");
    writeFile(dir + "/a.obj", std::string("mtllib m.mtl\n") + triangle + "usemtl m\nf 1 2 3\n");
    // Each m.mtl and the line it is rejected with.
    const std::pair<const char*, const char*> notNumbers[] = {
        {"newmtl m\nKd 0.5 half 0.5\n", "m.mtl:2: 'Kd' expects numbers, found 'half'"},
        {"newmtl m\nNi glass\n", "m.mtl:2: 'Ni' expects numbers, found 'glass'"}};
    for (const auto& [mtl, expected] : notNumbers) {
        writeFile(dir + "/m.mtl", mtl);
        expectRejected(dir, expected);
    }
}

TEST_CASE("numbers as tinyobjloader reads them: a tail after the number, nan, inf, out of range",
          "[scene][obj-leniency][solutions]") {
    const std::string dir = test::temporaryFolder("numbers");
    // Each odd vertex is read as tinyobjloader reads it, and the triangle stays the same one:
    // 0.0x is 0, 1.#IND (MSVC's NaN, its '#' inside a word and so no comment) is 1, nan is 0,
    // 1e-300 underflows to 0 and 1e+39 is beyond a float (0, with a warning, like nan).
    writeFile(dir + "/a.obj", "v 0.0x nan 1e-300\nv 1.#IND 0 1e+39\nv 0 1 -inf # a comment\n"
                              "f 1 2 3\n");
    const Rendered r =
        renderGrey(dir, {{"warning: " + dir +
                              "/a.obj:1: 'v' number '0.0x' has more after its number: PathLab "
                              "reads 0, as tinyobjloader does (and 1 more like it)",
                          "warning: " + dir +
                              "/a.obj:1: 'v' number 'nan' is not finite: PathLab reads it as 0, "
                              "as tinyobjloader does (and 1 more like it)",
                          "warning: " + dir +
                              "/a.obj:2: 'v' number '1e+39' is beyond a float's range: PathLab "
                              "reads it as 0"}});
    CHECK(!has(r.output, "1e-300"));

    const Scene scene = loadedObj(dir + "/a.obj");
    REQUIRE(scene.positions.size() >= 3);
    const Vec3 expected[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    for (int i = 0; i < 3; ++i) {
        CHECK(scene.positions[scene.triangles.at(0)[i]].x == expected[i].x);
        CHECK(scene.positions[scene.triangles.at(0)[i]].y == expected[i].y);
        CHECK(scene.positions[scene.triangles.at(0)[i]].z == expected[i].z);
    }
}

TEST_CASE("a face corner's texture or normal index past the file's list is dropped, with a "
          "warning; a vertex index past it stays an error",
          "[scene][obj-leniency][solutions]") {
    const std::string dir = test::temporaryFolder("indices");
    writeFile(dir + "/a.obj", std::string(triangle) + "vt 0 0\nf 1/1/1 2/7 3//2\n");
    renderGrey(dir, {{"warning: " + dir +
                          "/a.obj:5: face corner '1/1/1' refers to normal 1, but the file has 0: "
                          "PathLab reads the corner without it, as tinyobjloader reads past it "
                          "(and 1 more like it)",
                      "warning: " + dir +
                          "/a.obj:5: face corner '2/7' refers to texture coordinate 7, but the "
                          "file has 1: PathLab reads the corner without it"}});

    // Negative indices count back from the vertices before the face, as the format says.
    writeFile(dir + "/a.obj", "f -3 -2 -1\n" + std::string(triangle));
    expectRejected(dir, "a.obj:1: face corner '-3' refers to vertex -3, but the file has 0 "
                        "before this line");
}

TEST_CASE("keys PathLab does not model, in MTL and OBJ, and elements it does not draw: one note "
          "per file listing them",
          "[scene][obj-leniency][solutions]") {
    const std::string dir = test::temporaryFolder("ignored");
    writeFile(dir + "/m.mtl", "newmtl white\nKd 0.5 0.5 0.5\nd 0.5\nTr 0.5\nillum 2\n"
                              "map_Kd wood.png\nbump -bm 2 bumps.png\nshininess 4\nshininess 5\n");
    writeFile(dir + "/a.obj", std::string("mtllib m.mtl\n") + triangle +
                                  "o thing\ng group\ns 1\nwat 1 2\nusemtl white\n"
                                  "frobnicate\nf 1 2 3\nwat 3\nl 1 2\np 3\nl 2 3\n");
    renderGrey(dir, {{"note: " + dir +
                          "/m.mtl: PathLab models Kd, Ks, Kt/Tf, Ni, Ke, and Ns with illum 2; it "
                          "ignores Tr, bump, d, map_Kd, shininess\n",
                      "note: " + dir +
                          "/a.obj: PathLab ignores the OBJ keywords it does not know: "
                          "frobnicate, wat\n",
                      "note: " + dir +
                          "/a.obj: PathLab renders faces only; it leaves out the file's l, p\n"},
                     /*warnings*/ 0,
                     /*notes*/ 3});
}

TEST_CASE("long lines, no final newline, CRLF line ends, tabs and a UTF-8 BOM are read",
          "[scene][obj-leniency][solutions]") {
    const std::string dir = test::temporaryFolder("text");
    writeFile(dir + "/m.mtl", "\xEF\xBB\xBFnewmtl\twhite\r\nKd\t0.5 0.5\t0.5");
    std::string comment = "# " + std::string(100000, 'x') + "\r\n";
    writeFile(dir + "/a.obj", "\xEF\xBB\xBFmtllib m.mtl\r\n" + comment +
                                  "v\t0 0 0\r\nv 1\t0 0\r\nv 0 1 0 " + std::string(5000, ' ') +
                                  "\r\nusemtl white\r\n\tf 1 2 3");
    writeFile(dir + "/s.ecs", "\xEF\xBB\xBF-i a.obj\r\n-fov\t40\r\n");
    for (const char* file : {"a.obj", "s.ecs"}) {
        INFO(file);
        renderGrey(dir, {{}, /*warnings*/ 0, /*notes*/ 0}, file);
    }
}

TEST_CASE("what would make a wrong mesh stays an error of one line",
          "[scene][obj-leniency][bad-input]") {
    const std::string dir = test::temporaryFolder("errors");
    // Each a.obj and the line it is rejected with.
    const std::pair<std::string, const char*> wrongMeshes[] = {
        {"v 0 0 0\nv 1 zero 0\n", "a.obj:2: 'v' expects numbers, found 'zero'"},
        {std::string(triangle) + "f 1 2 9\n",
         "a.obj:4: face corner '9' refers to vertex 9, but the file has 3"},
        {std::string(triangle) + "f 1 2\n", "a.obj:4: a face needs at least 3 corners"},
        {std::string(triangle) + "l 1 2\n", "a.obj: no triangles (no 'f' line makes a triangle)"},
        {std::string(triangle) + "f 1 1 2\n",
         "a.obj: no triangles (its 1 triangle(s) have zero area)"},
        {"<?xml version=\"1.0\"?>\n<scene>\n</scene>\n",
         "a.obj: an Embree XML scene; PathLab reads OBJ"}};
    for (const auto& [obj, expected] : wrongMeshes) {
        writeFile(dir + "/a.obj", obj);
        expectRejected(dir, expected);
    }
    expectRejected(dir, "missing.obj: cannot open the OBJ file", "missing.obj");
}

TEST_CASE("UTF-16 files are named as such; words of other bytes are escaped",
          "[scene][obj-leniency][bad-input][solutions]") {
    const std::string dir = test::temporaryFolder("utf16");
    const auto utf16 = [](const std::string& ascii, bool bom) {
        std::string text = bom ? "\xFF\xFE" : "";
        for (const char c : ascii) text += std::string(1, c) + '\0';
        return text;
    };
    const auto expectClean = [](const std::string& output) {
        for (const char c : output) {
            const auto byte = static_cast<unsigned char>(c);
            CHECK(byte != 0);
            CHECK(byte < 0x80);
        }
    };
    writeFile(dir + "/a.obj", utf16(std::string(triangle) + "f 1 2 3\n", true));
    expectRejected(dir, "a.obj: looks like UTF-16 text (save it as UTF-8 or ASCII)");
    expectClean(render(dir).output);
    writeFile(dir + "/a.obj", utf16(std::string(triangle) + "f 1 2 3\n", false));
    expectRejected(dir, "a.obj: looks like UTF-16 text (save it as UTF-8 or ASCII)");
    writeFile(dir + "/s.ecs", utf16("-i a.obj\n", true));
    expectRejected(dir, "s.ecs: looks like UTF-16 text (save it as UTF-8 or ASCII)", "s.ecs");
    expectClean(render(dir, "s.ecs").output);
    writeFile(dir + "/m.mtl", utf16("newmtl white\n", true));
    writeFile(dir + "/a.obj", std::string("mtllib m.mtl\n") + triangle + "f 1 2 3\n");
    expectRejected(dir, "m.mtl: looks like UTF-16 text (save it as UTF-8 or ASCII)");

    writeFile(dir + "/m.mtl", "newmtl r\x1B[31md\nKd 0.5\xFF 0.5 0.5\n");
    writeFile(dir + "/a.obj", std::string("mtllib m.mtl\n") + triangle +
                                  "w\x01t\xC3\xA9 1\nusemtl caf\xC3\xA9\x07\nf 1 2 3\n");
    const Rendered r = render(dir);
    INFO(r.output);
    CHECK(r.exitStatus == 0);
    CHECK(has(r.output, "it does not know: w\\x01t\xC3\xA9\n"));
    CHECK(has(r.output, "material 'caf\xC3\xA9\\x07' is not defined"));
    CHECK(has(r.output, "'Kd' number '0.5\\xFF' is read as 0.5"));
    CHECK(r.output.find('\x1B') == std::string::npos);
    writeFile(dir + "/s.ecs", "-i a.obj\n-fr\x1B[2Job 1\n");
    expectRejected(dir, "s.ecs:2: unknown option '-fr\\x1B[2Job'", "s.ecs");
}

TEST_CASE("Ns is Ks's glossy exponent where the material says illum 2, and a mirror's 0 otherwise",
          "[scene][obj-leniency][solutions]") {
    const std::string dir = test::temporaryFolder("glossy");
    // In any order within the material; illum 3 (a ray-traced mirror) and a missing illum keep
    // Ks a mirror; an absurd Ns is ignored with a warning.
    writeFile(dir + "/m.mtl", "newmtl phong\nNs 40\nKs 0.5 0.5 0.5\nillum 2\n"
                              "newmtl first\nillum 2\nKs 0.3 0.3 0.3\nNs 7.5\n"
                              "newmtl mirror\nKs 0.5 0.5 0.5\nNs 40\nillum 3\n"
                              "newmtl unsaid\nKs 0.5 0.5 0.5\nNs 40\n"
                              "newmtl noexponent\nKs 0.5 0.5 0.5\nillum 2\n"
                              "newmtl absurd\nKs 0.5 0.5 0.5\nNs -3\nillum 2\n");
    writeFile(dir + "/a.obj", std::string("mtllib m.mtl\nusemtl phong\n") + triangle + "f 1 2 3\n");
    const Scene scene = loadedObj(dir + "/a.obj");
    CHECK(materialNamed(scene, "phong").Ns == 40.0f);
    CHECK(materialNamed(scene, "first").Ns == 7.5f);
    CHECK(materialNamed(scene, "mirror").Ns == 0.0f);
    CHECK(materialNamed(scene, "unsaid").Ns == 0.0f);
    CHECK(materialNamed(scene, "noexponent").Ns == 0.0f);
    CHECK(materialNamed(scene, "absurd").Ns == 0.0f);
    const Rendered r = render(dir);
    INFO(r.output);
    CHECK(r.output.find("m.mtl:21: 'Ns' (the Phong exponent) -3 is not between 0 and 1e+06: "
                        "ignored (Ks stays a mirror)") != std::string::npos);
    CHECK(r.output.find("m.mtl:18: material 'noexponent' says illum 2 (a Phong highlight) but "
                        "gives no Ns > 0: its Ks is a perfect mirror") != std::string::npos);
}
