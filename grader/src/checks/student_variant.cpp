#include "checks/student_variant.h"

#include "checks/correctness_check.h"
#include "checks/expectation.h"
#include "checks/grading_scenes.h"
#include "checks/scene_variants.h"
#include "common/content_hash.h"

#include "pathlab/support/input_error.h"
#include "pathlab/support/printable_text.h"
#include "pathlab/support/whole_file.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <random>

namespace pathlab::grader {

namespace fs = std::filesystem;

namespace {

constexpr size_t ShortestSecret = 16;
const char* const VariantFile = "variant.json";

double drawn(std::mt19937_64& engine, DrawRange range) {
    return range.low + (range.high - range.low) * portableUnit(engine);
}

/// A value as feedback and the files write it: rounded to 3 decimals, so that the scene's .mtl,
/// the analytic value and the words the student reads are of the same number.
double rounded(double value) { return std::round(value * 1000) / 1000; }

std::string furnaceName(const FurnaceModel& m) {
    char text[120];
    std::snprintf(text, sizeof text, "your furnace (albedo %g, Le %g, maxDepth %d)", m.reflectance,
                  m.emission, m.maxDepth);
    return text;
}

std::string boxName(const std::string& scene) { return "your variant of " + scene; }

/// The box's file stem: its seed's, so that the reference cache keeps one reference per student
/// (a cached reference is found by its scene's name, and checked against its files).
std::string boxStem(const StudentVariant& v) {
    char stem[40];
    std::snprintf(stem, sizeof stem, "box-%016llx", static_cast<unsigned long long>(v.boxSeed));
    return stem;
}

} // namespace

std::string classSecret(const VariantSettings& settings) {
    const std::string how = "write a secret of your own into it (at least " +
                            std::to_string(ShortestSecret) +
                            " characters: head -c 24 /dev/urandom | base64 > FILE) and keep it "
                            "from the students, as the hidden scenes";
    if (settings.secretFile.empty())
        throw InputError("the rubric's variants.per_student needs variants.secret_file, the file "
                         "of the class secret (a path relative to the rubric): " +
                         how);
    if (!fs::is_regular_file(settings.secretFile))
        throw InputError("variants.secret_file '" + settings.secretFile +
                         "' does not exist: " + how);
    std::string secret = readFile(settings.secretFile);
    while (!secret.empty() && (secret.back() == '\n' || secret.back() == '\r')) secret.pop_back();
    if (secret.size() < ShortestSecret)
        throw InputError("variants.secret_file '" + settings.secretFile + "' holds " +
                         std::to_string(secret.size()) + " characters: " + how);
    return secret;
}

StudentVariant drawStudentVariant(const VariantSettings& settings, const std::string& secret,
                                  const std::string& id) {
    const std::string hex = ContentHash().add("pathlab student variant").add(secret).add(id).hex();
    std::mt19937_64 engine(std::stoull(hex, nullptr, 16));
    StudentVariant v;
    v.id = id;
    v.furnace.walls = FurnaceWalls::Diffuse;
    v.furnace.reflectance = rounded(drawn(engine, settings.albedo));
    v.furnace.emission = rounded(drawn(engine, settings.emission));
    const int low = static_cast<int>(std::ceil(settings.maxDepth.low));
    const int high = static_cast<int>(std::floor(settings.maxDepth.high));
    v.furnace.maxDepth = low + static_cast<int>(portableUnit(engine) * (high - low + 1));
    v.boxSeed = engine();
    return v;
}

std::vector<GradingScene> studentVariantScenes(const Rubric& rubric, const StudentVariant& variant,
                                               const std::string& folder, const LabRunner& solution,
                                               const std::string& scratch,
                                               const std::string& cache) {
    const VariantSettings& s = rubric.variants;
    FurnaceModel furnace = variant.furnace;
    furnace.continueProb = rubric.continueProb;
    const std::string furnacePath = writeGreyMaterialScene(
        publicScenePath("furnace"), folder, "furnace", furnace.reflectance, furnace.emission);
    std::vector<GradingScene> scenes = {
        analyticFurnaceScene(rubric, furnacePath, furnace, furnaceName(furnace))};
    if (s.boxScene.empty()) return scenes;
    std::mt19937_64 engine(variant.boxSeed);
    const std::function<double()> random = [&] { return portableUnit(engine); };
    GradingScene box;
    box.path = writeVariedScene(publicScenePath(s.boxScene), folder, boxStem(variant), random,
                                s.reflectance, s.light);
    box.name = boxName(s.boxScene);
    box.reference = cachedOrMeasuredReference(solution, box.path, rubric, scratch, cache, box.name);
    scenes.push_back(std::move(box));
    return scenes;
}

std::vector<GradingScene>
writeStudentVariantFolder(const Rubric& rubric, const StudentVariant& variant,
                          const std::string& folder, const LabRunner& solution,
                          const std::string& scratch, const std::string& cache) {
    std::vector<GradingScene> scenes =
        studentVariantScenes(rubric, variant, folder, solution, scratch, cache);
    nlohmann::json j = {{"id", variant.id},
                        {"rubric_hash", rubric.hash},
                        {"kit_version", PATHLAB_VERSION},
                        {"furnace",
                         {{"albedo", variant.furnace.reflectance},
                          {"emission", variant.furnace.emission},
                          {"max_depth", variant.furnace.maxDepth}}}};
    if (scenes.size() > 1) {
        j["box"] = {{"scene", rubric.variants.boxScene},
                    {"file", fs::path(scenes[1].path).filename().string()}};
        fs::create_directories(folder + "/references");
        saveReference(folder + "/references", scenes[1].reference);
    }
    writeFileAtomically(folder + "/" + VariantFile, j.dump(2) + "\n");
    return scenes;
}

std::vector<GradingScene> loadStudentVariantFolder(const Rubric& rubric,
                                                   const std::string& folder) {
    const std::string file = folder + "/" + VariantFile;
    if (!fs::is_regular_file(file))
        throw InputError("variant '" + folder + "': no " + VariantFile +
                         " there; give the folder your instructor sent you");
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(readFile(file));
        FurnaceModel furnace;
        furnace.reflectance = j.at("furnace").at("albedo");
        furnace.emission = j.at("furnace").at("emission");
        furnace.maxDepth = j.at("furnace").at("max_depth");
        furnace.continueProb = rubric.continueProb;
        if (j.value("rubric_hash", "") != rubric.hash)
            throw InputError("variant '" + folder +
                             "' was made for another rubric than this release's: ask your "
                             "instructor for your variant of this one");
        if (j.value("kit_version", "") != PATHLAB_VERSION)
            throw InputError("variant '" + folder + "' was made by PathLab " +
                             printableText(j.value("kit_version", "?")) + ", this is " +
                             PATHLAB_VERSION +
                             ": ask your instructor for your variant of this one");
        std::vector<GradingScene> scenes = {analyticFurnaceScene(
            rubric, fs::absolute(folder + "/furnace.ecs").string(), furnace, furnaceName(furnace))};
        if (j.contains("box")) {
            GradingScene box;
            const std::string name = j.at("box").at("file");
            if (name.find('/') != std::string::npos || name.find("..") != std::string::npos)
                throw InputError(file + ": box.file must be a file of the folder");
            box.path = fs::absolute(folder + "/" + name).string();
            // Its words come from the folder: printed as text, never as terminal controls.
            box.name = boxName(printableText(j.at("box").at("scene").get<std::string>()));
            box.reference = loadReference(folder + "/references", box.path, rubric);
            scenes.push_back(std::move(box));
        }
        return scenes;
    } catch (const nlohmann::json::exception& e) {
        throw InputError(file + ": " + e.what());
    }
}

} // namespace pathlab::grader
