#include "pathlab/scene_io/obj_geometry.h"

#include "pathlab/scene_io/obj_fields.h"

#include <cstdlib>
#include <cstring>

namespace pathlab {

namespace {

using objfields::isSpace;

bool isLineEnd(char c) { return c == '\r' || c == '\n' || c == '\0'; }

/// A 1-based index (negative: back from `count`) as 0-based; false for 0.
bool fixIndex(int index, int count, int* fixed) {
    if (index == 0) return false;
    *fixed = index > 0 ? index - 1 : count + index;
    return true;
}

/// Moves past an index: up to '/', space, tab or CR.
void skipIndex(const char** token) { *token += std::strcspn(*token, "/ \t\r"); }

/// One corner, "v", "v/vt", "v//vn" or "v/vt/vn", read with atoi as tinyobjloader read it;
/// false where one of its indices is 0 (or no number).
bool readCorner(const char** token, int positions, int normals, int texcoords, ObjCorner* corner) {
    int texcoord = -1;
    *corner = ObjCorner{};
    if (!fixIndex(std::atoi(*token), positions, &corner->position)) return false;
    skipIndex(token);
    if ((*token)[0] != '/') return true;
    ++*token;
    if ((*token)[0] == '/') { // v//vn
        ++*token;
        if (!fixIndex(std::atoi(*token), normals, &corner->normal)) return false;
        skipIndex(token);
        return true;
    }
    if (!fixIndex(std::atoi(*token), texcoords, &texcoord)) return false;
    skipIndex(token);
    if ((*token)[0] != '/') return true;
    ++*token;
    if (!fixIndex(std::atoi(*token), normals, &corner->normal)) return false;
    skipIndex(token);
    return true;
}

std::string refusalOf(char key, int lineNumber) {
    const std::string what =
        key == 'f' ? "zero value for face index" : "zero value for vertex index";
    return "Failed parse `" + std::string(1, key) + "' line(e.g. " + what + ". line " +
           std::to_string(lineNumber) + ".)";
}

} // namespace

void ObjGeometryBuilder::line(std::string_view text, int lineNumber) {
    // Lines as tinyobjloader's safeGetline split them: at LF, CR LF or a lone CR.
    for (size_t start = 0;;) {
        size_t end = text.find_first_of("\r\n", start);
        if (end == std::string_view::npos) end = text.size();
        oneLine(std::string(text.substr(start, end - start)).c_str(), lineNumber++);
        if (end == text.size()) return;
        start = end + (text.compare(end, 2, "\r\n") == 0 ? 2 : 1);
    }
}

bool ObjGeometryBuilder::readCorners(const char* token, std::vector<ObjCorner>& corners) const {
    const int positions = static_cast<int>(geometry_.positions.size() / 3);
    const int normals = static_cast<int>(geometry_.normals.size());
    while (!isLineEnd(token[0])) {
        ObjCorner corner;
        if (!readCorner(&token, positions, normals, texcoords_, &corner)) return false;
        corners.push_back(corner);
        token += std::strspn(token, " \t\r");
    }
    return true;
}

void ObjGeometryBuilder::oneLine(const char* token, int lineNumber) {
    if (!geometry_.refusal.empty()) return; // tinyobjloader stopped at the first
    token += std::strspn(token, " \t");
    const char key = token[0];
    if (key == 'v' && isSpace(token[1])) {
        token += 2;
        for (int axis = 0; axis < 3; ++axis) geometry_.positions.push_back(objfields::real(&token));
    } else if (key == 'v' && token[1] == 'n' && isSpace(token[2])) {
        token += 3;
        const float x = objfields::real(&token), y = objfields::real(&token);
        geometry_.normals.push_back({x, y, objfields::real(&token)});
    } else if (key == 'v' && token[1] == 't' && isSpace(token[2])) {
        ++texcoords_;
    } else if ((key == 'l' || key == 'p' || key == 'f') && isSpace(token[1])) {
        token += 2;
        if (key == 'f') token += std::strspn(token, " \t");
        std::vector<ObjCorner> corners;
        if (!readCorners(token, corners)) {
            refuse(file_ + ": " + refusalOf(key, lineNumber));
        } else if (key == 'f') {
            pending_.push_back(std::move(corners));
        }
    } else if ((key == 'g' || key == 'o') && isSpace(token[1])) {
        cutPendingFaces();
    }
}

void ObjGeometryBuilder::useMaterial(int material) {
    if (!geometry_.refusal.empty() || material == material_) return;
    cutPendingFaces();
    material_ = material;
}

void ObjGeometryBuilder::refuse(const std::string& message) {
    if (geometry_.refusal.empty()) geometry_.refusal = message;
}

void ObjGeometryBuilder::cutPendingFaces() {
    std::vector<ObjCornerTriangle> triangles;
    for (const std::vector<ObjCorner>& face : pending_)
        cutObjFace(face, geometry_.positions, triangles);
    for (const ObjCornerTriangle& corners : triangles)
        geometry_.triangles.push_back({corners, material_});
    pending_.clear();
}

/// PathLab counts a 'v' or 'vn' line whose keyword is followed by other white space (a vertical
/// tab, a form feed) and checks the faces' indices against that count; tinyobjloader did not
/// read it, and read a vertex beyond its list for a face that uses the last ones.
void ObjGeometryBuilder::checkCorners() {
    const size_t positions = geometry_.positions.size() / 3, normals = geometry_.normals.size();
    for (const ObjTriangle& triangle : geometry_.triangles) {
        for (const ObjCorner& corner : triangle.corners) {
            const bool position = corner.position >= 0 && size_t(corner.position) < positions;
            const bool normal = corner.normal < 0 || size_t(corner.normal) < normals;
            if (position && normal) continue;
            geometry_.refusal =
                file_ + ": a face refers to " +
                (position ? "normal " + std::to_string(corner.normal + 1) + " of " +
                                std::to_string(normals) + " 'vn'"
                          : "vertex " + std::to_string(corner.position + 1) + " of " +
                                std::to_string(positions) + " 'v'") +
                " lines: a 'v' or 'vn' line counts only where a space or tab follows the keyword";
            return;
        }
    }
}

ObjGeometry ObjGeometryBuilder::finish() {
    if (geometry_.refusal.empty()) {
        cutPendingFaces();
        checkCorners();
    }
    return std::move(geometry_);
}

} // namespace pathlab
