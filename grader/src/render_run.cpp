#include "render_run.h"

#include "pathlab/image_io.h"
#include "pathlab/input_error.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

namespace pathlab::grader {

RenderResult renderLab(const RenderRequest& r, const ProcessLimits& limits) {
    namespace fs = std::filesystem;
    RenderResult result;
    const std::string image = r.scratch + "/render.exr", stats = r.scratch + "/render.json";
    fs::remove(image);
    fs::remove(stats);
    std::vector<std::string> argv = {
        r.viewer, "-c", r.scene, "--size", std::to_string(r.width), std::to_string(r.height),
        "--spp", std::to_string(r.spp), "--lab", std::string(labName(r.lab)),
        "--max-depth", std::to_string(r.maxDepth), "--continue-prob", std::to_string(r.continueProb),
        "--seed", std::to_string(r.seed), "-o", image, "--stats", stats};
    if (r.implementation == Implementation::Solution) argv.push_back("--solution");
    if (r.threads > 0) argv.insert(argv.end(), {"--threads", std::to_string(r.threads)});
    result.process = runProcess(argv, limits);
    if (!result.process.succeeded()) {
        result.failure = result.process.describe();
        return result;
    }
    try {
        std::ifstream in(stats);
        const nlohmann::json s = nlohmann::json::parse(in);
        result.nonfinitePixels = s.at("nonfinite_pixels");
        for (int c = 0; c < 3; ++c) result.meanVariance[c] = s.at("mean_variance").at(c);
        const Image read = readImage(image);
        // The lab runs in the process that writes this file: what it holds is checked, not trusted.
        if (read.width != r.width || read.height != r.height)
            throw std::runtime_error("the image is " + std::to_string(read.width) + "x" +
                                     std::to_string(read.height) + ", not the size asked for");
        result.image = read.rgb;
        result.width = read.width;
        result.height = read.height;
    } catch (const std::exception& e) {
        result.failure = std::string("its output could not be read: ") + e.what();
        return result;
    }
    if (result.nonfinitePixels > 0) {
        result.failure = "returned NaN or infinite radiance in " +
                         std::to_string(result.nonfinitePixels) +
                         " pixels (a division by a zero probability?)";
        return result;
    }
    result.ok = true;
    return result;
}

std::vector<double> regionMeans(const std::vector<float>& image, int width, int height, int tiles) {
    const int regions = 1 + tiles * tiles;
    std::vector<double> sums(3 * regions, 0.0);
    std::vector<double> counts(regions, 0.0);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const int tile = 1 + (y * tiles / height) * tiles + (x * tiles / width);
            for (int region : {0, tile}) {
                counts[region] += 1;
                for (int c = 0; c < 3; ++c)
                    sums[3 * region + c] += image[3 * (static_cast<size_t>(y) * width + x) + c];
            }
        }
    }
    for (int region = 0; region < regions; ++region)
        for (int c = 0; c < 3; ++c) sums[3 * region + c] /= counts[region];
    return sums;
}

} // namespace pathlab::grader
