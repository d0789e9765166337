#include "pathlab/scene_io/obj_reading.h"

#include "pathlab/support/input_error.h"
#include "pathlab/scene_io/mtl_reading.h"
#include "pathlab/scene_io/obj_number.h"
#include "pathlab/scene_io/polygon_triangulation.h"
#include "pathlab/support/printable_text.h"
#include "pathlab/support/text_file.h"

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <set>

namespace pathlab {

namespace {

namespace fs = std::filesystem;

std::string inQuotes(std::string_view word) { return "'" + printableText(word) + "'"; }

/// What a face corner's texture or normal index becomes when it points past the file's list.
struct DroppedIndex {
    int line = 0;
    std::string kind; ///< "texture coordinate" or "normal"
    std::string corner;
    long index = 0, count = 0;
};

/// Resolves one index of a face corner against the count of elements defined so far (negative
/// indices count back from there, as tinyobjloader and the format say) and in the whole file.
/// 0 when it is out of range; throws when it is not an index at all.
long resolveIndex(const std::string& file, const WordLine& line, std::string_view corner,
                  const std::string& text, long countSoFar, long countInFile) {
    char* end = nullptr;
    const long index = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || index == 0)
        throw inputErrorAt(file, line.number,
                           "face corner " + inQuotes(corner) +
                               " is not of the form "
                               "v, v/vt, v//vn or v/vt/vn with non-zero integers");
    const long resolved = index > 0 ? index : countSoFar + index + 1;
    return resolved >= 1 && resolved <= countInFile ? resolved : 0;
}

/// The elements of each kind an OBJ file defines, so far and in the whole file.
struct ElementCounts {
    long positions = 0, texcoords = 0, normals = 0;
};

// Keywords PathLab knows and reads past quietly: names, groups, smoothing and render hints,
// which change nothing it draws.
const std::set<std::string_view> quietObjKeys = {"o",     "g",     "s",          "mg",
                                                 "lod",   "bevel", "c_interp",   "d_interp",
                                                 "ctech", "stech", "shadow_obj", "trace_obj"};

// Elements other than faces: points, lines, curves and surfaces, and the data only they use.
// PathLab draws none of them, and says so once per file.
const std::set<std::string_view> leftOutObjKeys = {
    "p",    "l",    "vp",   "cstype", "deg",  "bmat", "step", "curv", "curv2",
    "surf", "parm", "trim", "hole",   "scrv", "sp",   "end",  "con"};

const char* leftOutIntro = "PathLab renders faces only; it leaves out the file's ";

const char* unknownIntro = "PathLab ignores the OBJ keywords it does not know: ";

/// The line ends in `text` as tinyobjloader counted them: LF, CR LF and a lone CR each one.
int lineBreaks(std::string_view text) {
    int breaks = 0;
    for (size_t i = 0; i < text.size(); ++i)
        breaks += text[i] == '\r' || (text[i] == '\n' && (i == 0 || text[i - 1] != '\r'));
    return breaks;
}

class ObjReader {
public:
    ObjReader(const std::string& path, InputNotes& notes)
        : path_(path), notes_(notes), geometry_(printableText(path)) {}

    ObjReading read(std::string_view text) {
        const std::vector<WordLine> lines = wordLines(text);
        if (!lines.empty() && lines[0].words[0][0] == '<')
            throw InputError(printableText(path_) + ": looks like XML, not OBJ");
        ElementCounts inFile;
        for (const WordLine& line : lines) {
            const std::string_view key = line.words[0];
            inFile.positions += key == "v";
            inFile.texcoords += key == "vt";
            inFile.normals += key == "vn";
        }
        ElementCounts soFar;
        size_t takenUpTo = 0; // the end of the line last given to geometry_
        int tinyobjLine = 1;
        for (const WordLine& line : lines) {
            const std::optional<std::string> replacement = readLine(line, soFar, inFile);
            // Each line as tinyobjloader was given it: a line rewritten where PathLab reads it
            // otherwise, the rest as in the file.
            const size_t start = static_cast<size_t>(line.text.data() - text.data());
            tinyobjLine += lineBreaks(text.substr(takenUpTo, start - takenUpTo));
            const std::string_view taken = replacement ? *replacement : line.text;
            geometry_.line(taken, tinyobjLine);
            tinyobjLine += lineBreaks(taken);
            takenUpTo = start + line.text.size();
        }
        reading_.geometry = geometry_.finish();
        warnAboutUndefinedMaterials();
        warnAboutDroppedIndices();
        return std::move(reading_);
    }

private:
    /// Reads one line: the line the geometry is to be built from where PathLab reads it
    /// otherwise than it is written ("" for one the geometry need not see), else nothing.
    std::optional<std::string> readLine(const WordLine& line, ElementCounts& soFar,
                                        const ElementCounts& inFile) {
        const std::string_view key = line.words[0];
        if (key == "v") {
            std::vector<float> xyz;
            auto replacement = readNumbers(line, 3, 7, &xyz); // x y z [w | r g b]
            positions_.push_back({xyz[0], xyz[1], xyz[2]});
            ++soFar.positions;
            return replacement;
        }
        if (key == "vn") {
            ++soFar.normals;
            return readNumbers(line, 3, 3);
        }
        if (key == "vt") {
            ++soFar.texcoords;
            return readNumbers(line, 1, 3);
        }
        if (key == "f") return readFace(line, soFar, inFile);
        if (key == "usemtl") return useMaterial(line);
        if (key == "mtllib") return materialLibraries(line);
        if (leftOutObjKeys.count(key)) {
            notes_.ignored(path_, leftOutIntro, std::string(key));
        } else if (!quietObjKeys.count(key)) {
            notes_.ignored(path_, unknownIntro, std::string(key));
            return ""; // the geometry need not guess at it
        }
        return std::nullopt;
    }

    /// Checks the count of numbers after the keyword, between `least` and `most`, and reads
    /// each as tinyobjloader does (readObjNumber); the line the geometry is then built from
    /// where a number was read differently from its word, else nothing.
    std::optional<std::string> readNumbers(const WordLine& line, size_t least, size_t most,
                                           std::vector<float>* values = nullptr) {
        const size_t count = line.words.size() - 1;
        const std::string key(line.words[0]);
        if (count < least || count > most) {
            const std::string expected =
                least == most ? std::to_string(least)
                              : std::to_string(least) + " to " + std::to_string(most);
            throw inputErrorAt(path_, line.number,
                               "'" + key + "' expects " + expected + " numbers, found " +
                                   std::to_string(count));
        }
        std::string rewritten = key;
        bool differs = false;
        for (size_t i = 1; i <= count; ++i) {
            const std::string_view word = line.words[i];
            const std::optional<ObjNumber> number = readObjNumber(word);
            if (!number)
                throw inputErrorAt(path_, line.number,
                                   "'" + key + "' expects numbers, found " + inQuotes(word));
            if (values) values->push_back(number->value);
            rewritten += ' ';
            if (number->reading == ObjNumberReading::exact) {
                rewritten += word;
                continue;
            }
            differs = true;
            char value[32];
            std::snprintf(value, sizeof value, "%.9g", number->value);
            rewritten += value;
            warnAboutNumber(line, key, word, *number);
        }
        if (!differs) return std::nullopt;
        return rewritten;
    }

    void warnAboutNumber(const WordLine& line, const std::string& key, std::string_view word,
                         const ObjNumber& number) {
        const std::string what = "'" + key + "' number " + inQuotes(word);
        switch (number.reading) {
        case ObjNumberReading::leadingPart: {
            char value[32];
            std::snprintf(value, sizeof value, "%g", number.value);
            return notes_.warning(path_, line.number, "leading number",
                                  what + " has more after its number: PathLab reads " + value +
                                      ", as tinyobjloader does");
        }
        case ObjNumberReading::notFinite:
            return notes_.warning(path_, line.number, "not finite",
                                  what + " is not finite: PathLab reads it as 0, as tinyobjloader "
                                         "does");
        case ObjNumberReading::beyondFloat:
            return notes_.warning(path_, line.number, "beyond float",
                                  what + " is beyond a float's range: PathLab reads it as 0");
        case ObjNumberReading::exact: return;
        }
    }

    /// Checks a face's corners. A vertex index out of range is an error (the triangle cannot be
    /// built); a texture or normal index out of range is dropped from its corner, as
    /// tinyobjloader reads past it with a warning: the face the geometry is then built from
    /// where an index was dropped, else nothing.
    std::optional<std::string> readFace(const WordLine& line, const ElementCounts& soFar,
                                        const ElementCounts& inFile) {
        if (line.words.size() < 4)
            throw inputErrorAt(path_, line.number, "a face needs at least 3 corners");
        std::string rewritten = "f";
        bool differs = false;
        std::vector<std::string> corners;
        std::vector<long> vertices; // 1-based
        for (size_t i = 1; i < line.words.size(); ++i) {
            const std::string_view corner = line.words[i];
            std::array<std::string, 3> part;
            size_t field = 0, start = 0;
            for (size_t k = 0; k <= corner.size(); ++k) {
                if (k == corner.size() || corner[k] == '/') {
                    if (field > 2)
                        throw inputErrorAt(path_, line.number,
                                           "face corner " + inQuotes(corner) + " has too many '/'");
                    part[field++] = corner.substr(start, k - start);
                    start = k + 1;
                }
            }
            const long vertex =
                resolveIndex(path_, line, corner, part[0], soFar.positions, inFile.positions);
            if (!vertex) {
                const long index = std::strtol(part[0].c_str(), nullptr, 10);
                throw inputErrorAt(
                    path_, line.number,
                    "face corner " + inQuotes(corner) + " refers to vertex " +
                        std::to_string(index) + ", but the file has " +
                        (index > 0 ? std::to_string(inFile.positions)
                                   : std::to_string(soFar.positions) + " before this line"));
            }
            const auto keep = [&](std::string& index, long countSoFar, long countInFile,
                                  const char* kind) {
                if (index.empty() ||
                    resolveIndex(path_, line, corner, index, countSoFar, countInFile))
                    return;
                dropped_.push_back({line.number, kind, std::string(corner),
                                    std::strtol(index.c_str(), nullptr, 10), countInFile});
                index.clear();
                differs = true;
            };
            if (field >= 2) keep(part[1], soFar.texcoords, inFile.texcoords, "texture coordinate");
            if (field == 3) keep(part[2], soFar.normals, inFile.normals, "normal");
            std::string kept = part[0];
            if (!part[2].empty())
                kept += '/' + part[1] + '/' + part[2];
            else if (!part[1].empty())
                kept += '/' + part[1];
            rewritten += ' ' + kept;
            corners.push_back(kept);
            vertices.push_back(vertex);
        }
        if (const auto cut = cutConcave(line, corners, vertices)) return cut;
        if (!differs) return std::nullopt;
        return rewritten;
    }

    /// The triangles of a concave face, as 'f' lines, where PathLab cuts it (tinyobjloader cuts
    /// a quad along its shorter diagonal and a larger polygon by its own ear clipping, either of
    /// which can cover more than a concave face); nothing for a convex face or a triangle,
    /// which tinyobjloader cuts as it always has, or a face of vertices defined after it.
    std::optional<std::string> cutConcave(const WordLine& line,
                                          const std::vector<std::string>& corners,
                                          const std::vector<long>& vertices) {
        if (corners.size() < 4) return std::nullopt;
        std::vector<Vec3> points;
        for (const long v : vertices) {
            if (v > static_cast<long>(positions_.size())) return std::nullopt;
            points.push_back(positions_[static_cast<size_t>(v - 1)]);
        }
        if (isConvexPolygon(points)) return std::nullopt;
        const auto triangles = earClip(points);
        const std::string face = "face of " + std::to_string(corners.size()) + " corners";
        if (!triangles) {
            notes_.warning(path_, line.number, "self-crossing face",
                           face + " is concave and crosses itself: tinyobjloader cuts it into "
                                  "triangles, which may cover more or less than it");
            return std::nullopt;
        }
        notes_.note(path_, line.number, "concave face",
                    face + " is concave: PathLab cuts it into triangles by ear clipping");
        std::string lines;
        for (const auto& t : *triangles)
            lines += (lines.empty() ? "f " : "\nf ") + corners[t[0]] + ' ' + corners[t[1]] + ' ' +
                     corners[t[2]];
        return lines;
    }

    void warnAboutDroppedIndices() {
        for (const DroppedIndex& d : dropped_) {
            notes_.warning(path_, d.line, d.kind + " index",
                           "face corner " + inQuotes(d.corner) + " refers to " + d.kind + " " +
                               std::to_string(d.index) + ", but the file has " +
                               std::to_string(d.count) + ": PathLab reads the corner without it, " +
                               "as tinyobjloader reads past it");
        }
    }

    /// Selects the first material of that name among those read so far, or none. A blank line
    /// stands for it, as tinyobjloader counted lines.
    std::string useMaterial(const WordLine& line) {
        const std::string name(line.rest);
        if (!defined_.count(name)) undefined_.push_back({line.number, name});
        const auto material = materialIndex_.find(name);
        geometry_.useMaterial(material == materialIndex_.end() ? -1 : material->second);
        return "";
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
        // Blank lines stand for it: one for each library found (tinyobjloader was given an
        // 'mtllib' line for each), one where none is.
        size_t found = 0;
        for (const std::string& name : libraryNames(line)) {
            const std::string file = (folder() / name).lexically_normal().string();
            auto known = libraryIndex_.find(file);
            if (known == libraryIndex_.end()) {
                known = libraryIndex_.emplace(file, readLibrary(line, name, file)).first;
            }
            found += known->second >= 0;
        }
        return std::string(found > 0 ? found - 1 : 0, '\n');
    }

    /// The index of the library in reading_.libraryFiles, or -1 for a file that is not there.
    int readLibrary(const WordLine& line, const std::string& name, const std::string& file) {
        if (!fs::is_regular_file(file)) {
            notes_.warning(path_, line.number, "mtllib not found",
                           "material library " + inQuotes(name) +
                               " not found: faces of its materials are grey (Kd 0.5)");
            reading_.greyFacesExplained = true;
            return -1;
        }
        const MaterialLibrary library = readMaterialLibrary(file, notes_);
        if (!library.refusal.empty()) geometry_.refuse(library.refusal);
        reading_.libraryFiles.push_back(file);
        for (size_t i = 0; i < library.names.size(); ++i) {
            const std::string& material = library.names[i];
            defined_.insert(material);
            definedAt_.emplace(material, line.number);
            materialIndex_.emplace(material, static_cast<int>(reading_.materials.size()));
            reading_.materials.push_back(library.materials[i]);
            reading_.materialNames.push_back(material);
        }
        return static_cast<int>(reading_.libraryFiles.size()) - 1;
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
    std::vector<DroppedIndex> dropped_;
    std::vector<Vec3> positions_; ///< the vertices read so far, for cutting concave faces
    std::map<std::string, int> materialIndex_; ///< the first of each name in reading_.materials
    ObjGeometryBuilder geometry_;
};

} // namespace

ObjReading readObj(const std::string& objPath, InputNotes& notes) {
    const std::string text = readTextFile(objPath, "the OBJ file");
    return ObjReader(objPath, notes).read(text);
}

} // namespace pathlab
