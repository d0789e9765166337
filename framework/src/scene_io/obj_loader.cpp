#include "pathlab/scene_io/obj_loader.h"

#include "pathlab/support/input_error.h"
#include "pathlab/scene_io/obj_reading.h"
#include "pathlab/support/printable_text.h"

#include <tiny_obj_loader.h>

#include <cctype>
#include <cstdio>
#include <map>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

namespace pathlab {

namespace {

Color toColor(const tinyobj::real_t c[3]) {
    return {static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2])};
}

Material toMaterial(const tinyobj::material_t& m) {
    Material material;
    material.Kd = toColor(m.diffuse);
    material.Ks = toColor(m.specular);
    material.Kt = toColor(m.transmittance); // tinyobjloader reads both Kt and Tf into it
    material.Ni = static_cast<float>(m.ior);
    material.Ke = toColor(m.emission);
    return material;
}

/// Hands tinyobjloader the material libraries as PathLab read them, for the "mtllib N" lines of
/// the text it is given, and gives their materials PathLab's names.
class ReadLibraries : public tinyobj::MaterialReader {
public:
    explicit ReadLibraries(const std::vector<MaterialLibrary>& libraries) : libraries_(libraries) {}

    bool operator()(const std::string& index, std::vector<tinyobj::material_t>* materials,
                    std::map<std::string, int>* names, std::string* warning,
                    std::string* error) override {
        const MaterialLibrary& library = libraries_.at(std::stoul(index));
        if (library.names.empty()) return true; // tinyobjloader would add a nameless material
        const size_t first = materials->size();
        std::istringstream text(library.textForTinyobj);
        tinyobj::LoadMtl(names, materials, &text, warning, error);
        if (materials->size() - first != library.names.size())
            throw std::logic_error(
                "tinyobjloader read " + std::to_string(materials->size() - first) +
                " materials of the " + std::to_string(library.names.size()) + " PathLab read");
        for (size_t i = 0; i < library.names.size(); ++i)
            (*materials)[first + i].name = library.names[i];
        return true;
    }

private:
    const std::vector<MaterialLibrary>& libraries_;
};

} // namespace

void loadObj(const std::string& objPath, Scene& scene) {
    // tinyobjloader skips what it cannot read and says little; PathLab's reading first turns
    // what would make a wrong mesh into an error naming its line, and every liberty it takes
    // into a warning or note.
    InputNotes notes;
    const ObjReading reading = readObj(objPath, notes);

    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warning, error;
    std::istringstream text(reading.textForTinyobj);
    ReadLibraries libraries(reading.libraries);
    if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warning, &error, &text, &libraries,
                          /*triangulate=*/true, /*default_vcols_fallback=*/false)) {
        while (!error.empty() && std::isspace(static_cast<unsigned char>(error.back())))
            error.pop_back(); // tinyobjloader ends its message with a line end
        throw InputError(printableText(objPath) + ": " +
                         (error.empty() ? "cannot be read" : printableText(error)));
    }

    const auto firstTriangle = scene.triangles.size();
    const auto firstMaterial = static_cast<uint32_t>(scene.materials.size());
    for (const tinyobj::material_t& m : materials) scene.addMaterial(m.name, toMaterial(m));
    uint32_t defaultMaterial = UINT32_MAX;

    // OBJ indexes positions and normals separately; Embree wants one index per vertex, so each
    // distinct (position, normal) pair becomes a vertex.
    std::unordered_map<uint64_t, uint32_t> vertexOf;
    auto vertex = [&](const tinyobj::index_t& index) {
        const uint64_t key = (static_cast<uint64_t>(index.vertex_index) << 32) |
                             static_cast<uint32_t>(index.normal_index);
        const auto [it, inserted] =
            vertexOf.emplace(key, static_cast<uint32_t>(scene.positions.size()));
        if (inserted) {
            const float* p = &attrib.vertices[3 * static_cast<size_t>(index.vertex_index)];
            scene.positions.push_back({p[0], p[1], p[2]});
            Vec3 n;
            if (index.normal_index >= 0) {
                const float* q = &attrib.normals[3 * static_cast<size_t>(index.normal_index)];
                n = {q[0], q[1], q[2]};
            }
            scene.vertexNormals.push_back(n);
        }
        return it->second;
    };

    int degenerate = 0;
    bool explainGrey = false;
    for (const tinyobj::shape_t& shape : shapes) {
        const auto& mesh = shape.mesh;
        for (size_t f = 0; f < mesh.num_face_vertices.size(); ++f) {
            const std::array<uint32_t, 3> tri = {vertex(mesh.indices[3 * f]),
                                                 vertex(mesh.indices[3 * f + 1]),
                                                 vertex(mesh.indices[3 * f + 2])};
            const Vec3 &a = scene.positions[tri[0]], &b = scene.positions[tri[1]],
                       &c = scene.positions[tri[2]];
            if (!(length(cross(b - a, c - a)) > 0)) {
                ++degenerate; // no area, no normal: it can never be hit meaningfully
                continue;
            }
            const int id = mesh.material_ids[f];
            uint32_t material;
            if (id >= 0) {
                material = firstMaterial + static_cast<uint32_t>(id);
            } else {
                if (defaultMaterial == UINT32_MAX) {
                    Material grey;
                    grey.Kd = Color(0.5f);
                    defaultMaterial = scene.addMaterial("(default)", grey);
                    explainGrey = !reading.greyFacesExplained;
                }
                material = defaultMaterial;
            }
            scene.triangles.push_back(tri);
            scene.triangleMaterials.push_back(material);
        }
    }
    if (scene.triangles.size() == firstTriangle)
        throw InputError(printableText(objPath) + ": no triangles (" +
                         (degenerate > 0
                              ? "its " + std::to_string(degenerate) + " triangle(s) have zero area"
                              : std::string("no 'f' line makes a triangle")) +
                         ")");
    notes.print();
    if (explainGrey)
        std::fprintf(stderr, "note: %s: faces without a material are grey (Kd 0.5)\n",
                     printableText(objPath).c_str());
    if (degenerate > 0)
        std::fprintf(stderr, "note: %s: skipped %d triangle(s) with zero area\n",
                     printableText(objPath).c_str(), degenerate);
}

} // namespace pathlab
