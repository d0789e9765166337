#include "pathlab/render_stats.h"

#include "pathlab/input_error.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace pathlab {

double RenderStats::samplesPerSecond() const {
    return seconds > 0 ? static_cast<double>(spp) * width * height / seconds : 0.0;
}

double RenderStats::raysPerSecond() const {
    return seconds > 0 ? static_cast<double>(rays.total()) / seconds : 0.0;
}

void writeFileAtomically(const std::string& path, const std::string& text) {
    namespace fs = std::filesystem;
    const fs::path target(path);
    const fs::path temporary =
        target.parent_path() / ("." + target.filename().string() + ".tmp" + std::to_string(::getpid()));
    {
        std::ofstream out(temporary, std::ios::binary);
        out << text;
        out.close();
        if (!out) {
            std::error_code ignored;
            fs::remove(temporary, ignored);
            throw InputError(path + ": cannot write the file");
        }
    }
    std::error_code error;
    fs::rename(temporary, target, error);
    if (error) {
        fs::remove(temporary, error);
        throw InputError(path + ": cannot move the finished file into place");
    }
}

void writeRenderStats(const std::string& path, const RenderStats& s) {
    auto rgb = [](const Color& c) { return nlohmann::json::array({c.r, c.g, c.b}); };
    const nlohmann::json json = {
        {"scene", s.scene},
        {"lab", s.lab},
        {"impl", s.impl},
        {"spp", s.spp},
        {"width", s.width},
        {"height", s.height},
        {"seed", s.seed},
        {"max_depth", s.maxDepth},
        {"continue_prob", s.continueProb},
        {"threads", s.threads},
        {"seconds", s.seconds},
        {"samples_per_second", s.samplesPerSecond()},
        {"rays", {{"intersect", s.rays.intersect}, {"occluded", s.rays.occluded}}},
        {"rays_per_second", s.raysPerSecond()},
        {"mean_radiance", rgb(s.meanRadiance)},
        {"mean_variance", rgb(s.meanVariance)},
        {"nonfinite_pixels", s.nonfinitePixels},
    };
    writeFileAtomically(path, json.dump(2) + "\n");
}

} // namespace pathlab
