#include "pathlab/obj_reading.h"

#include "pathlab/input_error.h"
#include "pathlab/parse_number.h"
#include "pathlab/printable_text.h"
#include "pathlab/text_file.h"

#include <array>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>

namespace pathlab {

namespace {

namespace fs = std::filesystem;

std::string inQuotes(std::string_view word) { return "'" + printableText(word) + "'"; }

/// Checks the numbers after the keyword, which must number between `least` and `most`.
void checkNumbers(const std::string& file, const WordLine& line, size_t least, size_t most) {
    const size_t count = line.words.size() - 1;
    const std::string key(line.words[0]);
    if (count < least || count > most) {
        const std::string expected = least == most
                                         ? std::to_string(least)
                                         : std::to_string(least) + " to " + std::to_string(most);
        throw inputErrorAt(file, line.number,
                           "'" + key + "' expects " + expected + " numbers, found " +
                               std::to_string(count));
    }
    for (size_t i = 1; i <= count; ++i)
        if (!parseFloat(line.words[i]))
            throw inputErrorAt(file, line.number,
                               "'" + key + "' expects numbers, found " + inQuotes(line.words[i]));
}

/// Checks one index of a face corner against the count of elements defined in the file.
void checkIndex(const std::string& file, const WordLine& line, std::string_view corner,
                const std::string& text, long count, const char* what) {
    char* end = nullptr;
    const long index = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || index == 0)
        throw inputErrorAt(file, line.number,
                           "face corner " + inQuotes(corner) +
                               " is not of the form "
                               "v, v/vt, v//vn or v/vt/vn with non-zero integers");
    const long resolved = index > 0 ? index : count + index + 1; // negative: counted backwards
    if (resolved < 1 || resolved > count)
        throw inputErrorAt(file, line.number,
                           "face corner " + inQuotes(corner) + " refers to " + what + " " +
                               std::to_string(index) + ", but the file has " +
                               std::to_string(count));
}

void checkFace(const std::string& file, const WordLine& line, long positions, long texcoords,
               long normals) {
    if (line.words.size() < 4)
        throw inputErrorAt(file, line.number, "a face needs at least 3 corners");
    for (size_t i = 1; i < line.words.size(); ++i) {
        const std::string_view corner = line.words[i];
        std::array<std::string, 3> part;
        size_t field = 0, start = 0;
        for (size_t k = 0; k <= corner.size(); ++k) {
            if (k == corner.size() || corner[k] == '/') {
                if (field > 2)
                    throw inputErrorAt(file, line.number,
                                       "face corner " + inQuotes(corner) + " has too many '/'");
                part[field++] = corner.substr(start, k - start);
                start = k + 1;
            }
        }
        checkIndex(file, line, corner, part[0], positions, "vertex");
        if (field >= 2 && !part[1].empty())
            checkIndex(file, line, corner, part[1], texcoords, "texture coordinate");
        if (field == 3) checkIndex(file, line, corner, part[2], normals, "normal");
    }
}

// Keywords PathLab knows and reads past, quietly: groups, smoothing, lines, points, curves.
const std::set<std::string_view> ignoredObjKeys = {
    "o",        "g",     "s",     "l",          "p",        "vp",   "mg",    "cstype",
    "deg",      "bmat",  "step",  "curv",       "curv2",    "surf", "parm",  "trim",
    "hole",     "scrv",  "sp",    "end",        "con",      "lod",  "bevel", "c_interp",
    "d_interp", "ctech", "stech", "shadow_obj", "trace_obj"};

const char* unknownIntro = "PathLab ignores the OBJ keywords it does not know: ";

class ObjReader {
public:
    ObjReader(const std::string& path, InputNotes& notes) : path_(path), notes_(notes) {}

    ObjReading read(std::string_view text) {
        const std::vector<WordLine> lines = wordLines(text);
        if (!lines.empty() && lines[0].words[0][0] == '<')
            throw InputError(printableText(path_) + ": looks like XML, not OBJ");
        long positions = 0, texcoords = 0, normals = 0;
        for (const WordLine& line : lines) {
            const std::string_view key = line.words[0];
            if (key == "v") checkNumbers(path_, line, 3, 7), ++positions; // x y z [w | r g b]
            if (key == "vn") checkNumbers(path_, line, 3, 3), ++normals;
            if (key == "vt") checkNumbers(path_, line, 1, 3), ++texcoords;
        }
        size_t forwardedUpTo = 0; // lines[] are views into `text`, which is forwarded in between
        for (const WordLine& line : lines) {
            const std::string_view key = line.words[0];
            std::string replacement;
            if (key == "f") {
                checkFace(path_, line, positions, texcoords, normals);
                continue;
            } else if (key == "usemtl") {
                replacement = useMaterial(line);
            } else if (key == "mtllib") {
                replacement = materialLibraries(line);
            } else if (key != "v" && key != "vn" && key != "vt" && !ignoredObjKeys.count(key)) {
                notes_.ignored(path_, unknownIntro, std::string(key));
            } else {
                continue;
            }
            const size_t start = static_cast<size_t>(line.text.data() - text.data());
            reading_.textForTinyobj.append(text.substr(forwardedUpTo, start - forwardedUpTo));
            reading_.textForTinyobj += replacement;
            forwardedUpTo = start + line.text.size();
        }
        reading_.textForTinyobj.append(text.substr(forwardedUpTo));
        warnAboutUndefinedMaterials();
        return std::move(reading_);
    }

private:
    std::string useMaterial(const WordLine& line) {
        const std::string name(line.rest);
        if (!defined_.count(name)) undefined_.push_back({line.number, name});
        return "usemtl " + tinyobjMaterialName(name);
    }

    /// The files of an 'mtllib' line: its words, or the whole rest of the line where that names
    /// a file (Blender writes a file name with spaces as it is).
    std::vector<std::string> libraryNames(const WordLine& line) const {
        if (line.words.size() > 2 && fs::is_regular_file(folder() / std::string(line.rest)))
            return {std::string(line.rest)};
        return {line.words.begin() + 1, line.words.end()};
    }

    std::string materialLibraries(const WordLine& line) {
        if (line.words.size() < 2) {
            notes_.warning(path_, line.number, "mtllib without file",
                           "'mtllib' without a file name: ignored");
            return "";
        }
        std::string replacement;
        for (const std::string& name : libraryNames(line)) {
            const std::string file = (folder() / name).lexically_normal().string();
            auto known = libraryIndex_.find(file);
            if (known == libraryIndex_.end()) {
                known = libraryIndex_.emplace(file, readLibrary(line, name, file)).first;
            }
            if (known->second < 0) continue;
            replacement +=
                (replacement.empty() ? "" : "\n") + ("mtllib " + std::to_string(known->second));
        }
        return replacement;
    }

    /// The index of the library in reading_.libraries, or -1 for a file that is not there.
    int readLibrary(const WordLine& line, const std::string& name, const std::string& file) {
        if (!fs::is_regular_file(file)) {
            notes_.warning(path_, line.number, "mtllib not found",
                           "material library " + inQuotes(name) +
                               " not found: faces of its materials are grey (Kd 0.5)");
            reading_.greyFacesExplained = true;
            return -1;
        }
        reading_.libraries.push_back(readMaterialLibrary(file, notes_));
        for (const std::string& material : reading_.libraries.back().names) {
            defined_.insert(material);
            definedAt_.emplace(material, line.number);
        }
        return static_cast<int>(reading_.libraries.size()) - 1;
    }

    /// tinyobjloader looks a 'usemtl' up among the materials read so far: a material defined by
    /// a later 'mtllib' is as undefined there as one defined nowhere.
    void warnAboutUndefinedMaterials() {
        for (const auto& [line, name] : undefined_) {
            const auto later = definedAt_.find(name);
            if (later != definedAt_.end())
                notes_.warning(path_, line, "used before mtllib",
                               "material " + inQuotes(name) +
                                   " is used before the 'mtllib' that defines it (line " +
                                   std::to_string(later->second) +
                                   "): its faces are grey (Kd 0.5), as tinyobjloader reads them");
            else
                notes_.warning(path_, line, "undefined material",
                               "material " + inQuotes(name) +
                                   " is not defined by any mtllib: its faces are grey (Kd 0.5)");
            reading_.greyFacesExplained = true;
        }
    }

    fs::path folder() const { return fs::path(path_).parent_path(); }

    const std::string& path_;
    InputNotes& notes_;
    ObjReading reading_;
    std::map<std::string, int> libraryIndex_; ///< by the file's path
    std::set<std::string> defined_;           ///< the materials of the libraries read so far
    std::map<std::string, int> definedAt_;    ///< the 'mtllib' line that defines each
    std::vector<std::pair<int, std::string>> undefined_;
};

} // namespace

ObjReading readObj(const std::string& objPath, InputNotes& notes) {
    const std::string text = readTextFile(objPath, "the OBJ file");
    return ObjReader(objPath, notes).read(text);
}

} // namespace pathlab
