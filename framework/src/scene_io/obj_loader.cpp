#include "pathlab/scene_io/obj_loader.h"

#include "pathlab/scene_io/obj_reading.h"
#include "pathlab/support/input_error.h"
#include "pathlab/support/printable_text.h"

#include <cstdio>
#include <unordered_map>

namespace pathlab {

namespace {

/// OBJ indexes positions and normals separately; Embree wants one index per vertex, so each
/// distinct (position, normal) pair becomes a vertex of the scene, in the order first used.
class SceneVertices {
public:
    SceneVertices(const ObjGeometry& geometry, Scene& scene) : geometry_(geometry), scene_(scene) {}

    uint32_t operator()(const ObjCorner& corner) {
        const uint64_t key =
            (static_cast<uint64_t>(corner.position) << 32) | static_cast<uint32_t>(corner.normal);
        const auto [it, inserted] =
            vertexOf_.emplace(key, static_cast<uint32_t>(scene_.positions.size()));
        if (inserted) {
            const size_t p = 3 * static_cast<size_t>(corner.position);
            scene_.positions.push_back({geometry_.positions.at(p), geometry_.positions.at(p + 1),
                                        geometry_.positions.at(p + 2)});
            scene_.vertexNormals.push_back(
                corner.normal >= 0 ? geometry_.normals.at(static_cast<size_t>(corner.normal))
                                   : Vec3());
        }
        return it->second;
    }

private:
    const ObjGeometry& geometry_;
    Scene& scene_;
    std::unordered_map<uint64_t, uint32_t> vertexOf_;
};

bool hasArea(const Scene& scene, const std::array<uint32_t, 3>& tri) {
    const Vec3 &a = scene.positions[tri[0]], &b = scene.positions[tri[1]],
               &c = scene.positions[tri[2]];
    return length(cross(b - a, c - a)) > 0;
}

} // namespace

void loadObj(const std::string& objPath, Scene& scene) {
    // PathLab's reading turns what would make a wrong mesh into an error naming its line, and
    // every liberty it takes into a warning or note; the mesh is the one tinyobjloader made of
    // the same lines, which the kit's scenes and references were made with.
    InputNotes notes;
    const ObjReading reading = readObj(objPath, notes);
    const ObjGeometry& geometry = reading.geometry;
    if (!geometry.refusal.empty()) throw InputError(geometry.refusal);

    const auto firstTriangle = scene.triangles.size();
    const auto firstMaterial = static_cast<uint32_t>(scene.materials.size());
    for (size_t i = 0; i < reading.materials.size(); ++i)
        scene.addMaterial(reading.materialNames[i], reading.materials[i]);
    uint32_t defaultMaterial = UINT32_MAX;
    SceneVertices vertex(geometry, scene);
    int degenerate = 0;
    for (const ObjTriangle& triangle : geometry.triangles) {
        const std::array<uint32_t, 3> tri = {
            vertex(triangle.corners[0]), vertex(triangle.corners[1]), vertex(triangle.corners[2])};
        if (!hasArea(scene, tri)) {
            ++degenerate; // no area, no normal: it can never be hit meaningfully
            continue;
        }
        if (triangle.material < 0 && defaultMaterial == UINT32_MAX) {
            Material grey;
            grey.Kd = Color(0.5f);
            defaultMaterial = scene.addMaterial("(default)", grey);
        }
        scene.triangles.push_back(tri);
        scene.triangleMaterials.push_back(
            triangle.material >= 0 ? firstMaterial + static_cast<uint32_t>(triangle.material)
                                   : defaultMaterial);
    }
    if (scene.triangles.size() == firstTriangle)
        throw InputError(printableText(objPath) + ": no triangles (" +
                         (degenerate > 0
                              ? "its " + std::to_string(degenerate) + " triangle(s) have zero area"
                              : std::string("no 'f' line makes a triangle")) +
                         ")");
    notes.print();
    if (defaultMaterial != UINT32_MAX && !reading.greyFacesExplained)
        std::fprintf(stderr, "note: %s: faces without a material are grey (Kd 0.5)\n",
                     printableText(objPath).c_str());
    if (degenerate > 0)
        std::fprintf(stderr, "note: %s: skipped %d triangle(s) with zero area\n",
                     printableText(objPath).c_str(), degenerate);
}

} // namespace pathlab
