// Image files and stats: formats, encodings, the JSON contract, and no NaN from any solution.
#include "catch.h"
#include "test_support.h"

#include "pathlab/images/image_io.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace pathlab;

TEST_CASE("EXR, PFM and HDR keep linear radiance; PNG is sRGB-encoded and clamped",
          "[render][images]") {
    const std::string dir = test::temporaryFolder("formats");
    const std::vector<float> rgb = {0.0f, 0.5f, 2.0f, 0.2f, 0.04f, 1.0f}; // 2×1 pixels
    for (const char* ext : {".exr", ".pfm", ".hdr"}) {
        const std::string path = dir + "/image" + ext;
        writeImage(path, 2, 1, rgb);
        const Image back = readImage(path);
        REQUIRE(back.width == 2);
        REQUIRE(back.height == 1);
        for (size_t i = 0; i < rgb.size(); ++i)
            // .hdr is RGBE: 8 bits of mantissa shared by the pixel, so up to max/256 off.
            CHECK(back.rgb[i] == Approx(rgb[i]).epsilon(0.01).margin(0.008));
    }
    writeImage(dir + "/image.png", 2, 1, rgb);
    const Image png = readImage(dir + "/image.png"); // decoded back to linear
    CHECK(png.rgb[1] == Approx(0.5f).epsilon(0.01));
    CHECK(png.rgb[2] == Approx(1.0f)); // clamped
    CHECK(linearToSrgb(0.5f) == Approx(0.7354f).epsilon(1e-3));
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        files += entry.is_regular_file();
    CHECK(files == 4); // no temporary files left behind
}

TEST_CASE("--stats writes the fields the README lists", "[render][stats][solutions]") {
    const std::string dir = test::temporaryFolder("stats");
    const auto run = test::runViewer("-c " + test::modelPath("furnace.ecs") +
                                     " --size 16 8 --spp 2 --lab roulette --solution --seed 3"
                                     " --continue-prob 0.5 -o " +
                                     dir + "/f.exr --stats " + dir + "/f.json");
    INFO(run.output);
    REQUIRE(run.exitStatus == 0);
    std::ifstream in(dir + "/f.json");
    const nlohmann::json stats = nlohmann::json::parse(in);
    CHECK(stats["scene"] == "furnace");
    CHECK(stats["lab"] == "roulette");
    CHECK(stats["impl"] == "solution");
    CHECK(stats["spp"] == 2);
    CHECK(stats["width"] == 16);
    CHECK(stats["height"] == 8);
    CHECK(stats["seed"] == 3);
    CHECK(stats["seconds"].get<double>() > 0);
    CHECK(stats["samples_per_second"].get<double>() > 0);
    CHECK(stats["rays"]["intersect"].get<uint64_t>() >= 16 * 8 * 2);
    CHECK(stats["rays"]["occluded"].get<uint64_t>() > 0);
    CHECK(stats["rays_per_second"].get<double>() > 0);
    CHECK(stats["mean_radiance"].size() == 3);
    CHECK(stats["nonfinite_pixels"] == 0);
    CHECK(stats["continue_prob"].get<double>() == Approx(0.5));
    // The figures a student writes down, each from the others as the README defines them.
    const double variance =
        (stats["mean_variance"][0].get<double>() + stats["mean_variance"][1].get<double>() +
         stats["mean_variance"][2].get<double>()) /
        3;
    const double radiance =
        (stats["mean_radiance"][0].get<double>() + stats["mean_radiance"][1].get<double>() +
         stats["mean_radiance"][2].get<double>()) /
        3;
    CHECK(stats["noise"].get<double>() == Approx(std::sqrt(variance / 2) / radiance));
    CHECK(stats["efficiency"].get<double>() ==
          Approx(1 / (std::pow(stats["noise"].get<double>(), 2) * stats["seconds"].get<double>())));
    CHECK(stats["frames_per_second"].get<double>() ==
          Approx(stats["samples_per_second"].get<double>() / (16 * 8)));
    CHECK(stats["frames_per_second_source"].get<std::string>().find("headless") !=
          std::string::npos);
    // And what the viewer writes, the grader's report reads back.
    const RenderStats read = readRenderStats(dir + "/f.json");
    CHECK(read.noise == Approx(stats["noise"].get<double>()));
    CHECK(read.framesPerSecond == Approx(stats["frames_per_second"].get<double>()));
    CHECK(read.rays.occluded == stats["rays"]["occluded"].get<uint64_t>());
    // The image on disk is the one the stats describe.
    const Image image = readImage(dir + "/f.exr");
    double sum = 0;
    for (size_t i = 0; i < image.rgb.size(); i += 3) sum += image.rgb[i];
    CHECK(sum / (16 * 8) == Approx(stats["mean_radiance"][0].get<double>()).epsilon(1e-4));
}

TEST_CASE("no reference solution writes a non-finite pixel", "[render][solutions]") {
    for (const char* scene : {"cornell_box_VI2_Specular.ecs", "furnace_glass.ecs"}) {
        for (Lab lab : AllLabs) {
            const auto result = test::render({"-c", test::modelPath(scene), "--size", "64", "64",
                                              "--spp", "4", "--lab", std::string(labName(lab)),
                                              "--solution", "--continue-prob", "0.5"});
            INFO(scene << " " << labName(lab));
            CHECK(result.stats.nonfinitePixels == 0);
            CHECK(isFinite(result.stats.meanRadiance));
            CHECK(result.stats.meanRadiance.r > 0);
        }
    }
}

TEST_CASE("the lab stubs compile, run, and render direct light only", "[render][solutions]") {
    // Direct light only: the stub and the solution at --max-depth 0 agree exactly, for every lab
    // but roulette (whose solution draws a roulette number even at the first hit).
    for (Lab lab : {Lab::Branching, Lab::Uniform, Lab::Importance}) {
        const std::vector<std::string> common = {"-c",
                                                 test::modelPath("cornell_box_diffuse.ecs"),
                                                 "--size",
                                                 "32",
                                                 "32",
                                                 "--spp",
                                                 "2",
                                                 "--lab",
                                                 std::string(labName(lab))};
        auto stubArgs = common;
        auto solutionArgs = common;
        solutionArgs.insert(solutionArgs.end(), {"--solution", "--max-depth", "0"});
        const auto stub = test::render(stubArgs).image.meanImage();
        const auto solution = test::render(solutionArgs).image.meanImage();
        INFO(labName(lab));
        CHECK(stub == solution);
    }
}
