#pragma once
/// The geometry of an OBJ file, built from its lines as PathLab takes them (each as in the
/// file, or as PathLab rewrote it: a number read otherwise, an index dropped, a concave face
/// cut): vertices, normals and triangles exactly as tinyobjloader 2.0.0rc10 built them from
/// the same lines, so that a scene loads bit for bit as it did when tinyobjloader read it.

#include "pathlab/scene_io/obj_face_cut.h"
#include "pathlab/vec3.h"

#include <string>
#include <string_view>
#include <vector>

namespace pathlab {

/// A triangle of an OBJ file and its material: an index into the materials of the libraries
/// read so far, -1 for none.
struct ObjTriangle {
    ObjCornerTriangle corners;
    int material = -1;
};

struct ObjGeometry {
    std::vector<float> positions; ///< x, y, z of each 'v' line
    std::vector<Vec3> normals;    ///< of each 'vn' line
    /// In the order of the faces in the file, each face's triangles in the order it is cut.
    std::vector<ObjTriangle> triangles;
    /// "FILE: problem" for what tinyobjloader refused, in its words: an 'f', 'l' or 'p' line it
    /// could not read (a corner of index 0, which PathLab's own checks leave through only on
    /// 'l' and 'p'), with its line number in the text it was given; or a face that refers to a
    /// vertex or normal of a 'v' or 'vn' line it did not read as one; or a material library
    /// that fails (MaterialLibrary::refusal). Empty when there was none; else the file loads no
    /// geometry.
    std::string refusal;
};

/// Builds an ObjGeometry line by line.
class ObjGeometryBuilder {
public:
    /// `file` names the OBJ file in a refusal.
    explicit ObjGeometryBuilder(std::string file) : file_(std::move(file)) {}
    /// A line as PathLab takes it; `lineNumber` is its number as tinyobjloader counted (a lone CR
    /// ends a line too). It may hold more than one line (a concave face cut into triangles).
    void line(std::string_view text, int lineNumber);
    /// A 'usemtl': the material of the faces from here on (-1: none).
    void useMaterial(int material);
    /// Fails the file with `message` ("FILE:LINE: problem"), unless it failed before.
    void refuse(const std::string& message);
    /// The geometry, once every line is given.
    ObjGeometry finish();

private:
    void oneLine(const char* token, int lineNumber);
    bool readCorners(const char* token, std::vector<ObjCorner>& corners) const;
    void cutPendingFaces();
    void checkCorners();

    std::string file_;
    ObjGeometry geometry_;
    int texcoords_ = 0;
    int material_ = -1;
    /// Faces not yet cut: tinyobjloader cut them at the next 'usemtl' that changed the material,
    /// 'g', 'o' or the file's end, against the vertices read by then.
    std::vector<std::vector<ObjCorner>> pending_;
};

} // namespace pathlab
