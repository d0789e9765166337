// viewer --seeds K: K images in one process, each the same file a separate run with that seed
// writes (the grader renders its seeds this way and relies on it).
#include "catch.h"
#include "test_support.h"

#include "pathlab/support/whole_file.h"

using namespace pathlab;

TEST_CASE("--seeds renders each seed as its own run would", "[render][solutions]") {
    const std::string folder = test::temporaryFolder("seeds");
    const std::string scene = "-c " + test::modelPath("cornell_box_VI2_Specular.ecs") +
                              " --size 16 12 --spp 3 --lab uniform --solution";
    const auto many = test::runViewer(scene + " --seed 40 --seeds 3 -o " + folder +
                                      "/many.pfm --stats " + folder + "/many.json");
    REQUIRE(many.exitStatus == 0);
    for (int seed : {40, 41, 42}) {
        const std::string one = folder + "/one-" + std::to_string(seed) + ".pfm";
        REQUIRE(
            test::runViewer(scene + " --seed " + std::to_string(seed) + " -o " + one).exitStatus ==
            0);
        const std::string image = readFile(folder + "/many-" + std::to_string(seed) + ".pfm");
        CHECK(!image.empty());
        CHECK(image == readFile(one));
        CHECK(readFile(folder + "/many-" + std::to_string(seed) + ".json")
                  .find("\"seed\": " + std::to_string(seed)) != std::string::npos);
    }
    // Different seeds, different images.
    CHECK(readFile(folder + "/many-40.pfm") != readFile(folder + "/many-41.pfm"));
}
