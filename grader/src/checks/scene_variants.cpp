#include "checks/scene_variants.h"

#include "checks/grading_scenes.h"
#include "common/scene_files.h"
#include "diagnosis/diagnosis.h"

#include "pathlab/support/input_error.h"
#include "pathlab/support/whole_file.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <random>
#include <sstream>

namespace pathlab::grader {

namespace {

namespace fs = std::filesystem;

/// `text` without its lines that begin with #.
std::string withoutComments(const std::string& text) {
    std::istringstream in(text);
    std::string out;
    for (std::string line; std::getline(in, line);)
        if (line.rfind('#', 0) != 0) out += line + "\n";
    return out;
}

/// Every occurrence of `from` in `text` replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
    for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
        text.replace(at, from.size(), to);
    return text;
}

} // namespace

namespace {

/// Writes the scene at `base` into `folder` under `stem` (stem.ecs, stem_NAME for the files it
/// names, each name replaced where another file names it), each file's text passed through
/// `transform` (its extension and text); returns the new .ecs's absolute path.
std::string
copyScene(const std::string& base, const std::string& folder, const std::string& stem,
          const std::function<std::string(const std::string&, std::string)>& transform) {
    fs::create_directories(folder);
    const std::vector<std::string> files = sceneFiles(base);
    std::vector<std::pair<std::string, std::string>> renamed;
    for (const std::string& file : files) {
        const std::string name = fs::path(file).filename().string();
        renamed.push_back({name, file == files.front() ? stem + ".ecs" : stem + "_" + name});
    }
    for (size_t i = 0; i < files.size(); ++i) {
        std::string text = readFile(files[i]);
        for (const auto& [from, to] : renamed) text = replaced(text, from, to);
        writeFileAtomically(folder + "/" + renamed[i].second,
                            transform(fs::path(files[i]).extension().string(), std::move(text)));
    }
    return fs::absolute(folder + "/" + stem + ".ecs").string();
}

/// The factor of each number after a line's first word, or none to leave the line as it is.
using NumberFactors = std::function<std::vector<double>(const std::string& word, size_t count)>;

/// `text` with the numbers after a line's first word multiplied by the factors `factorsOf`
/// gives them, each written with `digits` significant digits; other lines as they are.
std::string withScaledNumbers(const std::string& text, int digits, const NumberFactors& factorsOf) {
    std::istringstream in(text);
    std::string out;
    for (std::string line; std::getline(in, line);) {
        std::istringstream words(line);
        std::string word;
        words >> word;
        std::vector<double> values;
        for (double v; words >> v;) values.push_back(v);
        const std::vector<double> factors = factorsOf(word, values.size());
        if (!factors.empty()) {
            line = word;
            for (size_t k = 0; k < values.size(); ++k) {
                char number[40];
                std::snprintf(number, sizeof number, " %.*g", digits, values[k] * factors[k]);
                line += number;
            }
        }
        out += line + "\n";
    }
    return out;
}

/// "-pointlight X Y Z R G B" and "-dirlight DX DY DZ R G B" (one or two dashes, Embree's
/// spellings) with R G B times `factor`; other lines as they are.
std::string scaledLightOptions(const std::string& ecs, double factor) {
    return withScaledNumbers(ecs, 9, [factor](const std::string& option, size_t count) {
        const size_t dashes = option.find_first_not_of('-');
        const std::string name = option.substr(dashes == std::string::npos ? 0 : dashes);
        const bool light = name == "pointlight" || name == "dirlight" || name == "directionallight";
        return light && count == 6 ? std::vector<double>{1, 1, 1, factor, factor, factor}
                                   : std::vector<double>{};
    });
}

} // namespace

double portableUnit(std::mt19937_64& engine) {
    return static_cast<double>(engine() >> 11) * 0x1.0p-53;
}

std::string variedMaterials(const std::string& mtl, const std::function<double()>& random,
                            DrawRange reflectance, DrawRange light) {
    // Each value times a factor drawn within [low, high], one draw per value in order.
    return withScaledNumbers(mtl, 4, [&](const std::string& keyword, size_t count) {
        const bool diffuse = keyword == "Kd", emission = keyword == "Ke";
        const DrawRange range = diffuse ? reflectance : light;
        std::vector<double> factors;
        if (diffuse || emission)
            for (size_t k = 0; k < count; ++k)
                factors.push_back(range.low + (range.high - range.low) * random());
        return factors;
    });
}

std::string writeVariedScene(const std::string& ecsPath, const std::string& folder,
                             const std::string& stem, const std::function<double()>& random,
                             DrawRange reflectance, DrawRange light) {
    return copyScene(ecsPath, folder, stem, [&](const std::string& extension, std::string text) {
        if (extension == ".mtl") return variedMaterials(text, random, reflectance, light);
        // A scene lit by --pointlight or --dirlight (cornell_box_diffuse): its lights times one
        // factor drawn within `light`, as each Ke of an emissive material is.
        if (extension == ".ecs")
            return scaledLightOptions(text, light.low + (light.high - light.low) * random());
        return text;
    });
}

std::string writeGreyMaterialScene(const std::string& ecsPath, const std::string& folder,
                                   const std::string& stem, double albedo, double emission) {
    return copyScene(ecsPath, folder, stem, [&](const std::string& extension, std::string text) {
        if (extension == ".ecs") return withoutComments(text); // the public scene's numbers
        if (extension != ".mtl") return text;
        // Every digit kept: the analytic value is computed from these very numbers.
        char kd[80], ke[80];
        std::snprintf(kd, sizeof kd, "Kd %.17g %.17g %.17g", albedo, albedo, albedo);
        std::snprintf(ke, sizeof ke, "Ke %.17g %.17g %.17g", emission, emission, emission);
        std::istringstream in(text);
        std::string out;
        for (std::string line; std::getline(in, line);) {
            const std::string keyword = line.substr(0, line.find_first_of(" \t"));
            out += (keyword == "Kd" ? kd : keyword == "Ke" ? ke : line) + std::string("\n");
        }
        return out;
    });
}

std::string scaledEmission(const std::string& mtl, double factor) {
    // Every digit kept: a factor of 2^-6 must scale the light exactly.
    return withScaledNumbers(mtl, 17, [factor](const std::string& keyword, size_t count) {
        return keyword == "Ke" ? std::vector<double>(std::max<size_t>(count, 1), factor)
                               : std::vector<double>{};
    });
}

std::string writeScaledLightScene(const std::string& ecsPath, const std::string& folder,
                                  const std::string& stem, double factor) {
    return copyScene(ecsPath, folder, stem, [&](const std::string& extension, std::string text) {
        if (extension == ".mtl") return scaledEmission(text, factor);
        if (extension == ".ecs") return scaledLightOptions(text, factor);
        return text;
    });
}

std::vector<std::string> writeSceneVariants(const Rubric& rubric, const std::string& folder,
                                            uint64_t seed) {
    std::vector<std::string> bases;
    for (const std::string& name : rubric.scenes)
        if (!furnaceModel(name, rubric.maxDepth, rubric.continueProb)) bases.push_back(name);
    if (bases.empty() || rubric.sceneVariants <= 0) return {};
    std::mt19937_64 engine(seed);
    const std::function<double()> random = [&] { return portableUnit(engine); };
    std::vector<std::string> written;
    for (int k = 0; k < rubric.sceneVariants; ++k) {
        const std::string base = publicScenePath(bases[static_cast<size_t>(k) % bases.size()]);
        written.push_back(copyScene(base, folder, "variant_" + std::to_string(k + 1),
                                    [&](const std::string& extension, std::string text) {
                                        return extension == ".mtl" ? variedMaterials(text, random)
                                                                   : text;
                                    }));
    }
    return written;
}

} // namespace pathlab::grader
