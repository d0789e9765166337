#include "checks/variant_settings.h"

#include "pathlab/support/input_error.h"

#include <cstdio>
#include <filesystem>

namespace pathlab::grader {

namespace {

/// `section`'s [low, high] at `key`, kept as `range` when absent; throws InputError unless it
/// is two numbers, low <= high, within [least, most].
void readRange(const nlohmann::json& section, const char* key, const std::string& where,
               double least, double most, DrawRange& range) {
    if (!section.contains(key)) return;
    const nlohmann::json& v = section.at(key);
    const std::string name = where + "." + key;
    if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number())
        throw InputError(name + " must be two numbers [low, high]");
    range = {v[0].get<double>(), v[1].get<double>()};
    if (!(range.low <= range.high && range.low >= least && range.high <= most)) {
        char bounds[80];
        std::snprintf(bounds, sizeof bounds, " must lie within [%g, %g], low <= high", least, most);
        throw InputError(name + bounds);
    }
}

} // namespace

VariantSettings readVariantSettings(const nlohmann::json& section, const std::string& rubricPath) {
    VariantSettings s;
    if (section.is_null()) return s;
    const std::string where = rubricPath + ": variants";
    if (!section.is_object()) throw InputError(where + " must be an object");
    s.perStudent = section.value("per_student", false);
    if (!s.perStudent) return s;
    // A student release's rubric has no secret_file (its packaging leaves it out): it grades on
    // the student's variant folder, and only the instructor's commands ask for the secret.
    if (section.contains("secret_file")) {
        if (!section.at("secret_file").is_string())
            throw InputError(where + ".secret_file must name the file of the class secret (a "
                                     "path relative to the rubric), kept from the students");
        const std::filesystem::path file = section.at("secret_file").get<std::string>();
        s.secretFile =
            (file.is_absolute() ? file : std::filesystem::path(rubricPath).parent_path() / file)
                .lexically_normal()
                .string();
    }
    const nlohmann::json none = nlohmann::json::object();
    const nlohmann::json& furnace = section.contains("furnace") ? section.at("furnace") : none;
    // An albedo below 0.9 keeps lab 4's roulette of finite variance at the rubric's continueProb
    // (as furnace_a08 is graded); maxDepth 1 to 10 keeps the depth-limited value apart from Le.
    readRange(furnace, "albedo", where + ".furnace", 0.05, 0.9, s.albedo);
    readRange(furnace, "emission", where + ".furnace", 0.1, 10, s.emission);
    readRange(furnace, "max_depth", where + ".furnace", 1, 10, s.maxDepth);
    if (section.contains("box")) {
        const nlohmann::json& box = section.at("box");
        if (!box.is_object() || !box.contains("scene") || !box.at("scene").is_string())
            throw InputError(where + ".box.scene must name a public scene of models/, like "
                                     "cornell_box_diffuse");
        s.boxScene = box.at("scene").get<std::string>();
        // At most 1: no material reflects more than it did, so no box gains energy.
        readRange(box, "reflectance", where + ".box", 0.1, 1, s.reflectance);
        readRange(box, "light", where + ".box", 0.1, 10, s.light);
    }
    return s;
}

} // namespace pathlab::grader
