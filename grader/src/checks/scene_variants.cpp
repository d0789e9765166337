#include "checks/scene_variants.h"

#include "checks/grading_scenes.h"
#include "common/scene_files.h"
#include "diagnosis/diagnosis.h"

#include "pathlab/input_error.h"
#include "pathlab/whole_file.h"

#include <cstdio>
#include <filesystem>
#include <random>
#include <sstream>

namespace pathlab::grader {

namespace {

namespace fs = std::filesystem;

/// Every occurrence of `from` in `text` replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
    for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
        text.replace(at, from.size(), to);
    return text;
}

/// "Kd 0.5 0.5 0.5" with each value scaled by a factor drawn within [low, high].
std::string scaledLine(const std::string& keyword, std::istringstream& values, double low,
                       double high, const std::function<double()>& random) {
    std::string line = keyword;
    double value = 0;
    while (values >> value) {
        char text[32];
        std::snprintf(text, sizeof text, " %.4g", value * (low + (high - low) * random()));
        line += text;
    }
    return line;
}

} // namespace

std::string variedMaterials(const std::string& mtl, const std::function<double()>& random) {
    std::istringstream in(mtl);
    std::string out;
    for (std::string line; std::getline(in, line);) {
        std::istringstream words(line);
        std::string keyword;
        words >> keyword;
        if (keyword == "Kd")
            line = scaledLine(keyword, words, 0.5, 1.0, random);
        else if (keyword == "Ke")
            line = scaledLine(keyword, words, 0.6, 1.3, random);
        out += line + "\n";
    }
    return out;
}

std::vector<std::string> writeSceneVariants(const Rubric& rubric, const std::string& folder,
                                            uint64_t seed) {
    std::vector<std::string> bases;
    for (const std::string& name : rubric.scenes)
        if (!furnaceModel(name, rubric.maxDepth, rubric.continueProb)) bases.push_back(name);
    if (bases.empty() || rubric.sceneVariants <= 0) return {};
    fs::create_directories(folder);
    // The engine's numbers are the same on every platform; a distribution's are not.
    std::mt19937_64 engine(seed);
    const std::function<double()> random = [&] {
        return static_cast<double>(engine() >> 11) * 0x1.0p-53;
    };
    std::vector<std::string> written;
    for (int k = 0; k < rubric.sceneVariants; ++k) {
        const std::string base = publicScenePath(bases[static_cast<size_t>(k) % bases.size()]);
        const std::string stem = "variant_" + std::to_string(k + 1);
        // The scene's files under new names, each name replaced where another file names it.
        const std::vector<std::string> files = sceneFiles(base);
        std::vector<std::pair<std::string, std::string>> renamed;
        for (const std::string& file : files) {
            const std::string name = fs::path(file).filename().string();
            renamed.push_back({name, file == files.front() ? stem + ".ecs" : stem + "_" + name});
        }
        for (size_t i = 0; i < files.size(); ++i) {
            std::string text = readFile(files[i]);
            for (const auto& [from, to] : renamed) text = replaced(text, from, to);
            if (fs::path(files[i]).extension() == ".mtl") text = variedMaterials(text, random);
            writeFileAtomically(folder + "/" + renamed[i].second, text);
        }
        written.push_back(fs::absolute(folder + "/" + stem + ".ecs").string());
    }
    return written;
}

} // namespace pathlab::grader
