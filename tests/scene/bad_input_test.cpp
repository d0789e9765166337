// Every kind of bad input gets one clear line naming the file:line or the option, exit status 2,
// and no output written (an existing file of the same name is left as it was). What PathLab
// reads with a warning instead (odd MTL values, undefined materials, unknown keywords) is in
// obj_leniency_test.cpp.
#include "catch.h"
#include "test_support.h"

#include "pathlab/render/lab_registry.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#if !defined(_WIN32)
#include <unistd.h>
#endif

using namespace pathlab;

namespace {

namespace fs = std::filesystem;

void writeFile(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

std::string readFile(const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

const char* goodMtl = "newmtl white\nKd 0.5 0.5 0.5\n";
const char* goodObj = "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl white\nf 1 2 3\n";

/// Runs the viewer on a scene folder holding m.mtl, a.obj and s.ecs, with one of them replaced,
/// and checks the failure: status 2, the expected words, nothing written over "out.png".
void expectRejected(const std::string& file, const std::string& contents,
                    const std::string& expected, const std::string& extraArguments = "") {
    const std::string dir = test::temporaryFolder("bad");
    writeFile(dir + "/m.mtl", goodMtl);
    writeFile(dir + "/a.obj", goodObj);
    writeFile(dir + "/s.ecs", "-i a.obj\n-vp 0.3 0.3 -2 -vi 0.3 0.3 0\n");
    writeFile(dir + "/" + file, contents);
    writeFile(dir + "/out.png", "previous image");
    const auto run = test::runViewer("-c " + dir + "/s.ecs --size 8 8 --spp 1 -o " + dir +
                                     "/out.png " + extraArguments);
    INFO("output: " << run.output);
    CHECK(run.exitStatus == 2);
    CHECK(run.output.find(expected) != std::string::npos);
    CHECK(std::count(run.output.begin(), run.output.end(), '\n') <= 2);
    CHECK(readFile(dir + "/out.png") == "previous image");
    int files = 0;
    for (const auto& entry : fs::directory_iterator(dir)) files += entry.is_regular_file();
    CHECK(files == 4); // no temporary file left behind
}

} // namespace

TEST_CASE("malformed OBJ lines are named by file and line", "[scene][bad-input]") {
    expectRejected("a.obj", "v 0 0 0\nv 1 0\n", "a.obj:2: 'v' expects 3 to 7 numbers, found 2");
    expectRejected("a.obj", "v 0 0 0\nv 1 zero 0\n", "a.obj:2: 'v' expects numbers, found 'zero'");
    expectRejected("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n",
                   "a.obj:4: face corner '9' refers to vertex 9, but the file has 3");
    expectRejected("a.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n",
                   "a.obj:3: a face needs at least 3 corners");
    expectRejected("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/x 2 3\n", "a.obj:4: face corner '1/x'");
}

TEST_CASE("malformed scene scripts are named by file and line", "[scene][bad-input]") {
    expectRejected("s.ecs", "-i a.obj\n-vp 1 2\n", "s.ecs:2: option -vp needs three numbers");
    expectRejected("s.ecs", "-i a.obj\n-vp 1 2 x\n", "s.ecs:2: option -vp expects three numbers");
    expectRejected("s.ecs", "-i a.obj\n-frobnicate 3\n", "s.ecs:2: unknown option '-frobnicate'");
    expectRejected("s.ecs", "# nothing here\n-i missing.obj\n",
                   "missing.obj: cannot open the OBJ file");
    expectRejected("s.ecs", "-i a.obj -fov 0\n", "s.ecs:1: option -fov expects an angle");
}

TEST_CASE("nonsensical options are named", "[scene][bad-input]") {
    expectRejected("a.obj", goodObj, "unknown option '--sparkle'", "--sparkle");
    expectRejected("a.obj", goodObj, "option --spp expects samples per pixel (1..", "--spp 0");
    expectRejected("a.obj", goodObj, "option --continue-prob expects a probability strictly",
                   "--continue-prob 0");
    expectRejected("a.obj", goodObj, "option --continue-prob expects a probability strictly",
                   "--continue-prob 1.5");
    expectRejected("a.obj", goodObj, "option --max-depth expects a depth from 0", "--max-depth -1");
    expectRejected("a.obj", goodObj, "option --size expects a width in pixels", "--size 0 8");
    expectRejected("a.obj", goodObj,
                   "option --lab expects one of " + pathlab::labNames(", ") + ", got 'fancy'",
                   "--lab fancy");
    expectRejected("a.obj", goodObj, "option --threads expects", "--threads lots");
}

TEST_CASE("missing files and unwritable outputs are named", "[scene][bad-input]") {
    auto run = test::runViewer("-c /nonexistent/scene.ecs -o /tmp/x.png");
    CHECK(run.exitStatus == 2);
    CHECK(run.output.find("/nonexistent/scene.ecs: cannot open the scene script") !=
          std::string::npos);

    const std::string scene = test::modelPath("furnace.ecs");
    run = test::runViewer("-c " + scene + " -o /nonexistent-folder/out.png");
    CHECK(run.exitStatus == 2);
    CHECK(run.output.find("folder '/nonexistent-folder' does not exist") != std::string::npos);

    run = test::runViewer("-c " + scene + " -o out.txt");
    CHECK(run.exitStatus == 2);
    CHECK(run.output.find("must end in .exr, .pfm, .hdr") != std::string::npos);

#if !defined(_WIN32)        // a folder's permission bits do not stop writes on Windows
    if (::geteuid() != 0) { // root may write anywhere
        const std::string dir = test::temporaryFolder("readonly");
        fs::permissions(dir, fs::perms::owner_read | fs::perms::owner_exec);
        run = test::runViewer("-c " + scene + " -o " + dir + "/out.png");
        CHECK(run.exitStatus == 2);
        CHECK(run.output.find("is not writable") != std::string::npos);
        fs::permissions(dir, fs::perms::owner_all);
    }
#endif

    run = test::runViewer("--spp 4");
    CHECK(run.exitStatus == 2);
    CHECK(run.output.find("no scene given") != std::string::npos);
}

TEST_CASE("a material that reflects more than it receives is named in a warning",
          "[scene][bad-input]") {
    const std::string dir = test::temporaryFolder("energy");
    writeFile(dir + "/m.mtl", "newmtl shiny\nKd 0.8 0.2 0.2\nKs 0.5 0.5 0.5\n");
    writeFile(dir + "/a.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl shiny\nf 1 2 3\n");
    const auto run =
        test::runViewer("-i " + dir + "/a.obj --size 4 4 --spp 1 -o " + dir + "/o.png");
    INFO(run.output);
    CHECK(run.exitStatus == 0);
    CHECK(run.output.find("warning: " + dir +
                          "/m.mtl:1: material 'shiny' is not energy "
                          "conserving: Kd+Ks+Kt = 1.3 in red") != std::string::npos);
}
