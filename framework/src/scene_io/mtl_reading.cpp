#include "pathlab/scene_io/mtl_reading.h"

#include "pathlab/support/input_error.h"
#include "pathlab/scene_io/mtl_values.h"
#include "pathlab/scene_io/obj_number.h"
#include "pathlab/support/parse_number.h"
#include "pathlab/support/printable_text.h"
#include "pathlab/support/text_file.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <optional>
#include <set>

namespace pathlab {

namespace {

const std::set<std::string_view> colourKeys = {"Kd", "Ks", "Kt", "Tf", "Ke"};

const char* ignoredIntro = "PathLab models Kd, Ks, Kt/Tf, Ni, Ke, and Ns with illum 2; it ignores ";

// A Phong exponent beyond this is a mirror in all but name (its lobe is narrower than a
// hundredth of a degree), and float's cosⁿ underflows for most directions in it.
constexpr float mostNs = 1.0e6f;

// Outside this, an index of refraction is an exporter's placeholder (Ni 0, Ni 0.001) or a typo:
// glass is 1.5, diamond 2.4, nothing a scene holds beyond 4.
constexpr float leastNi = 0.1f, mostNi = 10.0f;

std::string inQuotes(std::string_view word) { return "'" + printableText(word) + "'"; }

/// The energy a material's Kd, Ks and Kt send on, for the warning where it exceeds 1.
struct Energy {
    std::string name;
    int line = 0;
    std::array<float, 3> Kd{}, Ks{}, Kt{};
};

class MtlReader {
public:
    MtlReader(const std::string& path, InputNotes& notes) : path_(path), notes_(notes) {}

    MaterialLibrary read(std::string_view text) {
        const std::vector<WordLine> lines = wordLines(text);
        for (const WordLine& line : lines) readLine(line);
        finishMaterial();
        warnAboutEnergy();
        library_.materials = values_.materials();
        for (size_t i = 0; i < std::min(library_.materials.size(), glossyExponents_.size()); ++i)
            library_.materials[i].Ns = glossyExponents_[i];
        return std::move(library_);
    }

private:
    void readLine(const WordLine& line) {
        const std::string_view key = line.words[0];
        if (key == "newmtl") return newMaterial(line);
        const bool modelled = colourKeys.count(key) || key == "Ni" || key == "Ns" || key == "illum";
        if (!library_.names.empty()) noteOpacity(line);
        if (key == "Tf" && !library_.names.empty()) {
            filter_ = &line; // read when the material ends, once its d or Tr is known
        } else if (!modelled) {
            notes_.ignored(path_, ignoredIntro, std::string(key));
            // Taken: tinyobjloader gave a material with map_Kd and no Kd a Kd of 0.6.
            if (!library_.names.empty()) take(line, line.text);
        } else if (library_.names.empty()) {
            notes_.warning(path_, line.number, "before newmtl",
                           inQuotes(key) + " comes before any 'newmtl': ignored");
        } else if (key == "Ni") {
            readNi(line);
        } else if (key == "Ns" || key == "illum") {
            readGlossiness(line);
        } else {
            readColour(line);
        }
    }

    /// Whether the material says it is opaque: 'd 1' or 'Tr 0', which exporters write beside a
    /// 'Tf 1 1 1' that then filters nothing.
    void noteOpacity(const WordLine& line) {
        if (line.words.size() < 2) return;
        const std::optional<float> value = parseFloat(line.words[1]);
        if (line.words[0] == "d" && value == 1.0f) opaque_ = true;
        if (line.words[0] == "Tr" && value == 0.0f) opaque_ = true;
    }

    /// A 'Tf' (transmission filter) is the material's transmission, as tinyobjloader reads it,
    /// unless the material says it is opaque.
    void finishMaterial() {
        finishGlossiness();
        if (filter_ && opaque_) {
            notes_.warning(path_, filter_->number, "Tf on opaque",
                           "'Tf' on a material that says it is opaque ('d 1' or 'Tr 0'): "
                           "PathLab ignores it (read as transmission, 'Tf 1 1 1' would make "
                           "the material clear glass)");
        } else if (filter_) {
            readColour(*filter_);
        }
        filter_ = nullptr;
        opaque_ = false;
    }

    /// 'Ns' (the Phong exponent) and 'illum' (the illumination model): Ks is a glossy lobe of
    /// exponent Ns where the material says illum 2 ("highlight on", the MTL format's Phong
    /// model) and gives Ns > 0, and a perfect mirror otherwise (illum 3 and above are the
    /// format's ray-traced mirrors).
    void readGlossiness(const WordLine& line) {
        const bool exponent = line.words[0] == "Ns";
        if (line.words.size() < 2) {
            notes_.warning(path_, line.number, std::string(line.words[0]) + " count",
                           inQuotes(line.words[0]) + " expects 1 number, found 0: ignored");
            return;
        }
        const float value = numberIn(line, line.words[1]);
        if (!exponent) {
            illum_ = value;
            illumLine_ = line.number;
        } else if (value >= 0 && value <= mostNs) {
            exponent_ = value;
        } else {
            char range[64];
            std::snprintf(range, sizeof range, "between 0 and %g", mostNs);
            notes_.warning(path_, line.number, "Ns absurd",
                           "'Ns' (the Phong exponent) " + printableText(line.words[1]) +
                               " is not " + range + ": ignored (Ks stays a mirror)");
        }
    }

    void finishGlossiness() {
        if (library_.names.empty()) return;
        float glossy = 0.0f;
        if (illum_ == 2.0f && exponent_ > 0.0f) glossy = exponent_;
        if (illum_ == 2.0f && exponent_ <= 0.0f && energy_.back().Ks != std::array<float, 3>{})
            notes_.note(path_, illumLine_, "illum 2 without Ns",
                        "material " + inQuotes(library_.names.back()) +
                            " says illum 2 (a Phong highlight) but gives no Ns > 0: its Ks is a "
                            "perfect mirror");
        glossyExponents_.push_back(glossy);
        illum_ = -1.0f;
        exponent_ = 0.0f;
    }

    void newMaterial(const WordLine& line) {
        finishMaterial();
        const std::string name(line.rest);
        if (name.empty()) {
            notes_.warning(path_, line.number, "empty newmtl",
                           "'newmtl' without a name: PathLab names the material '' (a 'usemtl' "
                           "without a name selects it)");
        } else if (line.words.size() > 2) {
            notes_.note(path_, line.number, "name with spaces",
                        "material name " + inQuotes(name) +
                            " has spaces: PathLab reads the whole rest of the line as the name, "
                            "in 'newmtl' and 'usemtl' alike (tinyobjloader's 'usemtl' would read "
                            "only " +
                            inQuotes(line.words[1]) + ")");
        }
        library_.names.push_back(name);
        energy_.push_back({name, line.number, {}, {}, {}});
        values_.newMaterial();
    }

    /// r g b; the MTL format's "Kd r" means grey, which tinyobjloader reads as (r, 0, 0).
    void readColour(const WordLine& line) {
        const std::string key(line.words[0]);
        const size_t count = line.words.size() - 1;
        if (count == 0) {
            notes_.warning(path_, line.number, key + " without numbers",
                           inQuotes(key) + " without numbers: ignored");
            return;
        }
        std::vector<std::string> words;
        bool rewritten = count != 3;
        for (size_t i = 0; i < std::min<size_t>(count, 3); ++i) {
            words.emplace_back(line.words[i + 1]);
            float value = numberIn(line, words[i]);
            if (value < 0) {
                notes_.warning(path_, line.number, key + " negative",
                               inQuotes(key) + " cannot be negative: PathLab reads " +
                                   printableText(words[i]) + " as 0");
                value = 0;
            }
            if (parseFloat(words[i]) == value) continue;
            char written[32];
            std::snprintf(written, sizeof written, "%.9g", value);
            words[i] = written;
            rewritten = true;
        }
        if (count == 1) words = {words[0], words[0], words[0]};
        if (count == 2) words.emplace_back("0");
        std::array<float, 3> values{};
        for (size_t i = 0; i < 3; ++i) values[i] = parseFloat(words[i]).value_or(0.0f);
        if (count == 1) {
            notes_.note(path_, line.number, key + " grey",
                        inQuotes(key + " " + std::string(line.words[1])) +
                            " has one number: PathLab reads it as " + "grey (" +
                            printableText(words[0] + " " + words[0] + " " + words[0]) +
                            "), as the MTL format says");
        } else if (count == 2) {
            notes_.warning(path_, line.number, key + " two numbers",
                           inQuotes(key) +
                               " expects 3 numbers (r g b), found 2: PathLab reads blue as 0");
        } else if (count > 3) {
            notes_.warning(path_, line.number, key + " extra numbers",
                           inQuotes(key) + " expects 3 numbers (r g b), found " +
                               std::to_string(count) + ": PathLab reads the first 3");
        }
        Energy& m = energy_.back();
        if (key == "Kd") m.Kd = values;
        if (key == "Ks") m.Ks = values;
        if (key == "Kt" || key == "Tf") m.Kt = values;
        take(line, rewritten ? key + " " + words[0] + " " + words[1] + " " + words[2]
                             : std::string(line.text));
    }

    /// A word of a colour or Ni line as a number: what is no number at all ("half") is an error
    /// naming its line, as in an OBJ file; a word that is one with more after it, or nan or
    /// inf, is read as tinyobjloader reads it, with a warning.
    float numberIn(const WordLine& line, std::string_view word) {
        if (const std::optional<float> exact = parseFloat(word)) return *exact;
        const std::string key(line.words[0]);
        const std::optional<ObjNumber> number = readObjNumber(word);
        if (!number)
            throw inputErrorAt(path_, line.number,
                               inQuotes(key) + " expects numbers, found " + inQuotes(word));
        char value[32];
        std::snprintf(value, sizeof value, "%g", number->value);
        notes_.warning(path_, line.number, key + " odd number",
                       inQuotes(key) + " number " + inQuotes(word) + " is read as " + value +
                           ", as tinyobjloader reads it");
        return number->value;
    }

    void readNi(const WordLine& line) {
        const size_t count = line.words.size() - 1;
        const char* assumed = ": PathLab uses 1 (tinyobjloader's default)";
        if (count == 0) {
            notes_.warning(path_, line.number, "Ni count",
                           std::string("'Ni' expects 1 number, found 0") + assumed);
            return take(line, "Ni 1");
        }
        const float ni = numberIn(line, line.words[1]);
        if (!(ni >= leastNi && ni <= mostNi)) {
            char range[64];
            std::snprintf(range, sizeof range, "between %g and %g", leastNi, mostNi);
            notes_.warning(path_, line.number, "Ni absurd",
                           "'Ni' (index of refraction) " + printableText(line.words[1]) +
                               (ni > 0 ? " is not " + std::string(range) : " must be > 0") +
                               assumed);
            return take(line, "Ni 1");
        }
        if (count > 1)
            notes_.warning(path_, line.number, "Ni count",
                           "'Ni' expects 1 number, found " + std::to_string(count) +
                               ": PathLab reads the first");
        char written[32];
        std::snprintf(written, sizeof written, "Ni %.9g", ni);
        take(line,
             count == 1 && parseFloat(line.words[1]) == ni ? std::string(line.text) : written);
    }

    void warnAboutEnergy() {
        static const char* channel[3] = {"red", "green", "blue"};
        for (const Energy& m : energy_) {
            for (int c = 0; c < 3; ++c) {
                const float sum = m.Kd[c] + m.Ks[c] + m.Kt[c];
                if (sum > 1.0f + 1e-6f) {
                    char text[64];
                    std::snprintf(text, sizeof text, "Kd+Ks+Kt = %g in %s exceeds 1", sum,
                                  channel[c]);
                    notes_.warning(path_, m.line, "energy",
                                   "material " + inQuotes(m.name) + " is not energy conserving: " +
                                       text + ": PathLab uses the values as written");
                    break;
                }
            }
        }
    }

    /// Takes a line of the current material, as it is or as PathLab rewrote it.
    void take(const WordLine& line, std::string_view text) {
        if (!values_.line(text) && library_.refusal.empty())
            library_.refusal = inputErrorAt(path_, line.number,
                                            "a lone CR (an old Mac line end) starts a 'newmtl' "
                                            "within this line: save the file with LF or CR LF "
                                            "line ends")
                                   .what();
    }

    const std::string& path_;
    InputNotes& notes_;
    MaterialLibrary library_;
    MtlValues values_; ///< the values of each line as PathLab takes it
    std::vector<Energy> energy_;
    const WordLine* filter_ = nullptr;      ///< the current material's 'Tf' line, if it has one
    bool opaque_ = false;                   ///< the current material says 'd 1' or 'Tr 0'
    float illum_ = -1.0f, exponent_ = 0.0f; ///< the current material's illum and Ns
    int illumLine_ = 0;
    std::vector<float> glossyExponents_; ///< each material's Material::Ns
};

} // namespace

MaterialLibrary readMaterialLibrary(const std::string& mtlPath, InputNotes& notes) {
    const std::string text = readTextFile(mtlPath, "the material file");
    return MtlReader(mtlPath, notes).read(text);
}

} // namespace pathlab
