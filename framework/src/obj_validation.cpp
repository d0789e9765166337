#include "pathlab/obj_validation.h"

#include "pathlab/input_error.h"
#include "pathlab/parse_number.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace pathlab {

namespace {

namespace fs = std::filesystem;

struct Line {
    int number;
    std::vector<std::string> words;
};

std::vector<Line> readLines(const std::string& path, const char* kind) {
    std::ifstream in(path);
    if (!in) throw InputError(path + ": cannot open the " + kind + " file");
    std::vector<Line> lines;
    std::string text;
    for (int number = 1; std::getline(in, text); ++number) {
        if (const size_t hash = text.find('#'); hash != std::string::npos) text.erase(hash);
        std::istringstream stream(text);
        Line line{number, {}};
        for (std::string word; stream >> word;) line.words.push_back(word);
        if (!line.words.empty()) lines.push_back(std::move(line));
    }
    return lines;
}

bool parseNumber(const std::string& word, float& value) {
    const std::optional<float> number = parseFloat(word);
    if (number) value = *number;
    return number.has_value();
}

/// The numbers after the keyword, which must number between `least` and `most`.
std::vector<float> numbers(const std::string& file, const Line& line, size_t least, size_t most) {
    const size_t count = line.words.size() - 1;
    const std::string& key = line.words[0];
    if (count < least || count > most) {
        const std::string expected = least == most
                                         ? std::to_string(least)
                                         : std::to_string(least) + " to " + std::to_string(most);
        throw inputErrorAt(file, line.number,
                           "'" + key + "' expects " + expected + " numbers, found " +
                               std::to_string(count));
    }
    std::vector<float> values(count);
    for (size_t i = 0; i < count; ++i)
        if (!parseNumber(line.words[i + 1], values[i]))
            throw inputErrorAt(file, line.number,
                               "'" + key + "' expects numbers, found '" + line.words[i + 1] + "'");
    return values;
}

/// Checks one index of a face corner against the count of elements defined in the file.
void checkIndex(const std::string& file, const Line& line, const std::string& corner,
                const std::string& text, long count, const char* what) {
    char* end = nullptr;
    const long index = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || index == 0)
        throw inputErrorAt(file, line.number,
                           "face corner '" + corner +
                               "' is not of the form "
                               "v, v/vt, v//vn or v/vt/vn with non-zero integers");
    const long resolved = index > 0 ? index : count + index + 1; // negative: counted backwards
    if (resolved < 1 || resolved > count)
        throw inputErrorAt(file, line.number,
                           "face corner '" + corner + "' refers to " + what + " " +
                               std::to_string(index) + ", but the file has " +
                               std::to_string(count));
}

const std::set<std::string> ignoredObjKeys = {
    "o",        "g",     "s",     "l",          "p",        "vp",   "mg",    "cstype",
    "deg",      "bmat",  "step",  "curv",       "curv2",    "surf", "parm",  "trim",
    "hole",     "scrv",  "sp",    "end",        "con",      "lod",  "bevel", "c_interp",
    "d_interp", "ctech", "stech", "shadow_obj", "trace_obj"};

const std::set<std::string> ignoredMtlKeys = {
    "Ns", "illum", "Ka",    "d",      "Tr",   "sharpness", "Pr",    "Pm",   "Ps",
    "Pc", "Pcr",   "aniso", "anisor", "bump", "disp",      "decal", "refl", "norm"};

} // namespace

std::vector<std::string> validateMtl(const std::string& mtlPath) {
    std::vector<std::string> names;
    std::set<std::string> ignored;
    struct Energy {
        std::string name;
        int line = 0;
        std::array<float, 3> Kd{}, Ks{}, Kt{};
    };
    std::vector<Energy> materials;

    for (const Line& line : readLines(mtlPath, "material")) {
        const std::string& key = line.words[0];
        if (key == "newmtl") {
            if (line.words.size() != 2)
                throw inputErrorAt(mtlPath, line.number, "'newmtl' expects one material name");
            names.push_back(line.words[1]);
            materials.push_back({line.words[1], line.number, {}, {}, {}});
        } else if (key == "Kd" || key == "Ks" || key == "Kt" || key == "Tf" || key == "Ke") {
            if (materials.empty())
                throw inputErrorAt(mtlPath, line.number, "'" + key + "' comes before any 'newmtl'");
            // Three numbers, r g b: tinyobjloader would read a lone "Kd 0.5" as (0.5, 0, 0).
            const std::vector<float> c = numbers(mtlPath, line, 3, 3);
            if (*std::min_element(c.begin(), c.end()) < 0)
                throw inputErrorAt(mtlPath, line.number, "'" + key + "' cannot be negative");
            Energy& m = materials.back();
            std::array<float, 3> value = {c[0], c[1], c[2]};
            if (key == "Kd") m.Kd = value;
            if (key == "Ks") m.Ks = value;
            if (key == "Kt" || key == "Tf") m.Kt = value;
        } else if (key == "Ni") {
            if (materials.empty())
                throw inputErrorAt(mtlPath, line.number, "'Ni' comes before any 'newmtl'");
            const float ni = numbers(mtlPath, line, 1, 1)[0];
            if (!(ni > 0))
                throw inputErrorAt(mtlPath, line.number, "'Ni' (index of refraction) must be > 0");
        } else if (ignoredMtlKeys.count(key) || key.rfind("map_", 0) == 0) {
            ignored.insert(key);
        } else {
            throw inputErrorAt(mtlPath, line.number, "unknown material keyword '" + key + "'");
        }
    }

    if (!ignored.empty()) {
        std::string keys;
        for (const std::string& k : ignored) keys += (keys.empty() ? "" : ", ") + k;
        std::fprintf(stderr, "note: %s: PathLab models Kd, Ks, Kt/Tf, Ni and Ke; it ignores %s\n",
                     mtlPath.c_str(), keys.c_str());
    }
    for (const Energy& m : materials) {
        static const char* channel[3] = {"red", "green", "blue"};
        for (int c = 0; c < 3; ++c) {
            const float sum = m.Kd[c] + m.Ks[c] + m.Kt[c];
            if (sum > 1.0f + 1e-6f) {
                std::fprintf(stderr,
                             "warning: %s:%d: material '%s' is not energy conserving: "
                             "Kd+Ks+Kt = %g in %s exceeds 1\n",
                             mtlPath.c_str(), m.line, m.name.c_str(), sum, channel[c]);
                break;
            }
        }
    }
    return names;
}

void validateObj(const std::string& objPath) {
    const std::vector<Line> lines = readLines(objPath, "OBJ");
    long positions = 0, texcoords = 0, normals = 0;
    std::set<std::string> materials;
    for (const Line& line : lines) {
        const std::string& key = line.words[0];
        if (key == "v") {
            numbers(objPath, line, 3, 7), ++positions; // x y z [w] or x y z r g b
        } else if (key == "vn") {
            numbers(objPath, line, 3, 3), ++normals;
        } else if (key == "vt") {
            numbers(objPath, line, 1, 3), ++texcoords;
        } else if (key == "mtllib") {
            if (line.words.size() < 2)
                throw inputErrorAt(objPath, line.number, "'mtllib' expects a file name");
            for (size_t i = 1; i < line.words.size(); ++i) {
                const fs::path mtl = fs::path(objPath).parent_path() / line.words[i];
                if (!fs::exists(mtl))
                    throw inputErrorAt(objPath, line.number,
                                       "material library '" + line.words[i] + "' not found");
                for (const std::string& name : validateMtl(mtl.string())) materials.insert(name);
            }
        }
    }
    for (const Line& line : lines) {
        const std::string& key = line.words[0];
        if (key == "f") {
            if (line.words.size() < 4)
                throw inputErrorAt(objPath, line.number, "a face needs at least 3 corners");
            for (size_t i = 1; i < line.words.size(); ++i) {
                const std::string& corner = line.words[i];
                std::array<std::string, 3> part;
                size_t field = 0, start = 0;
                for (size_t k = 0; k <= corner.size(); ++k) {
                    if (k == corner.size() || corner[k] == '/') {
                        if (field > 2)
                            throw inputErrorAt(objPath, line.number,
                                               "face corner '" + corner + "' has too many '/'");
                        part[field++] = corner.substr(start, k - start);
                        start = k + 1;
                    }
                }
                checkIndex(objPath, line, corner, part[0], positions, "vertex");
                if (field >= 2 && !part[1].empty())
                    checkIndex(objPath, line, corner, part[1], texcoords, "texture coordinate");
                if (field == 3) checkIndex(objPath, line, corner, part[2], normals, "normal");
            }
        } else if (key == "usemtl") {
            if (line.words.size() != 2)
                throw inputErrorAt(objPath, line.number, "'usemtl' expects one material name");
            if (!materials.count(line.words[1]))
                throw inputErrorAt(objPath, line.number,
                                   "material '" + line.words[1] + "' is not defined by any mtllib");
        } else if (key != "v" && key != "vn" && key != "vt" && key != "mtllib" &&
                   !ignoredObjKeys.count(key)) {
            throw inputErrorAt(objPath, line.number, "unknown OBJ keyword '" + key + "'");
        }
    }
}

} // namespace pathlab
