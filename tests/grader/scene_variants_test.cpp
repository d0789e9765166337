// The variants of the public scenes a batch grades on when the instructor keeps no hidden scenes
// (checks/scene_variants.h): the same seed the same files; another seed other colours; the light
// and the diffuse colours changed within their ranges, nothing else; the files loadable as the
// grader's scene files.
#include "catch.h"

#include "checks/rubric.h"
#include "checks/scene_variants.h"
#include "common/scene_files.h"

#include "pathlab/support/whole_file.h"

#include <filesystem>
#include <sstream>
#include <unistd.h>

using namespace pathlab;
using namespace pathlab::grader;

namespace fs = std::filesystem;

namespace {

/// A fresh folder, removed with the object.
struct Folder {
    std::string path;
    Folder() {
        char pattern[] = "/tmp/pathlab-variants-XXXXXX";
        path = ::mkdtemp(pattern);
    }
    ~Folder() { fs::remove_all(path); }
};

/// The values of every line of `mtl` that starts with `keyword`, in order.
std::vector<double> values(const std::string& mtl, const std::string& keyword) {
    std::istringstream in(mtl);
    std::vector<double> found;
    for (std::string line; std::getline(in, line);) {
        std::istringstream words(line);
        std::string first;
        words >> first;
        for (double v; first == keyword && words >> v;) found.push_back(v);
    }
    return found;
}

} // namespace

TEST_CASE("a seed makes the same variant files, another seed other ones", "[grader]") {
    const Rubric rubric = loadRubric(std::string(PATHLAB_GRADER_DIR) + "/rubric.json");
    REQUIRE(rubric.sceneVariants == 1);
    Folder a, b, c;
    const std::vector<std::string> written = writeSceneVariants(rubric, a.path, 42);
    REQUIRE(written.size() == 1);
    writeSceneVariants(rubric, b.path, 42);
    writeSceneVariants(rubric, c.path, 43);
    // The VI2 box (the first public scene that is not a furnace), under the variant's names.
    const std::vector<std::string> files = sceneFiles(written.front());
    REQUIRE(files.size() == 3);
    CHECK(fs::path(files[1]).filename() == "variant_1_cornell_box_VI2_Specular.obj");
    for (const std::string& file : files) {
        const std::string name = fs::path(file).filename().string();
        CHECK(readFile(file) == readFile(b.path + "/" + name));
    }
    const std::string mtl = readFile(files[2]);
    CHECK(mtl != readFile(c.path + "/" + fs::path(files[2]).filename().string()));
    // Within their ranges of the public scene's values; Ks, Kt, Ni as they were.
    const std::string original =
        readFile(std::string(PATHLAB_MODELS_DIR) + "/cornell_box_VI2_Specular.mtl");
    const std::vector<double> kd = values(mtl, "Kd"), kdBefore = values(original, "Kd");
    REQUIRE(kd.size() == kdBefore.size());
    for (size_t i = 0; i < kd.size(); ++i) {
        CHECK(kd[i] <= kdBefore[i] + 1e-6);
        CHECK(kd[i] >= 0.5 * kdBefore[i] - 1e-6);
    }
    const std::vector<double> ke = values(mtl, "Ke"), keBefore = values(original, "Ke");
    REQUIRE(ke.size() == 3);
    for (size_t i = 0; i < ke.size(); ++i)
        CHECK((ke[i] >= 0.6 * keBefore[i] && ke[i] <= 1.3 * keBefore[i]));
    for (const char* kept : {"Ks", "Kt", "Ni"}) CHECK(values(mtl, kept) == values(original, kept));
    CHECK(kd != kdBefore);
}

TEST_CASE("no variants where the rubric asks for none", "[grader]") {
    Rubric rubric = loadRubric(std::string(PATHLAB_GRADER_DIR) + "/rubric.json");
    rubric.sceneVariants = 0;
    Folder folder;
    CHECK(writeSceneVariants(rubric, folder.path, 42).empty());
    CHECK(fs::is_empty(folder.path));
}
