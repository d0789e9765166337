#include "pathlab/scene_io/mtl_values.h"

#include "pathlab/scene_io/obj_fields.h"

#include <cstring>
#include <string>

namespace pathlab {

namespace {

using objfields::isSpace;

/// `key` (two letters) followed by a space or tab.
bool isKey(const char* token, const char* key) {
    return token[0] == key[0] && token[1] == key[1] && isSpace(token[2]);
}

Color readColor(const char* token) {
    token += 2;
    const float r = objfields::real(&token), g = objfields::real(&token);
    return {r, g, objfields::real(&token)};
}

} // namespace

void MtlValues::newMaterial() { materials_.emplace_back(); }

bool MtlValues::line(std::string_view text) {
    // Lines as tinyobjloader's safeGetline split them: at LF, CR LF or a lone CR.
    for (size_t start = 0;;) {
        size_t end = text.find_first_of("\r\n", start);
        if (end == std::string_view::npos) end = text.size();
        std::string line(text.substr(start, end - start));
        line.erase(line.find_last_not_of(" \t") + 1); // all of it where it is only white space
        if (!oneLine(line.c_str())) return false;
        if (end == text.size()) return true;
        start = end + (text.compare(end, 2, "\r\n") == 0 ? 2 : 1);
    }
}

bool MtlValues::oneLine(const char* token) {
    token += std::strspn(token, " \t");
    if (std::strncmp(token, "newmtl", 6) == 0 && isSpace(token[6])) return false;
    if (materials_.empty() || token[0] == '\0' || token[0] == '#') return true;
    Material& m = materials_.back();
    if (isKey(token, "Kd")) {
        m.Kd = readColor(token);
        fileHasKd_ = true;
    } else if (isKey(token, "Ks")) {
        m.Ks = readColor(token);
    } else if (isKey(token, "Kt") || isKey(token, "Tf")) {
        m.Kt = readColor(token);
    } else if (isKey(token, "Ni")) {
        token += 2;
        m.Ni = objfields::real(&token);
    } else if (isKey(token, "Ke")) {
        m.Ke = readColor(token);
    } else if (std::strncmp(token, "map_Kd", 6) == 0 && isSpace(token[6]) && !fileHasKd_) {
        m.Kd = Color(0.6f);
    }
    return true;
}

} // namespace pathlab
