#include "pathlab/obj_loader.h"

#include "pathlab/input_error.h"
#include "pathlab/obj_validation.h"

#include <tiny_obj_loader.h>

#include <cstdio>
#include <filesystem>
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

} // namespace

void loadObj(const std::string& objPath, Scene& scene) {
    // tinyobjloader is lenient (it skips what it cannot read); our own pass first turns every
    // malformed line into an error that names it.
    validateObj(objPath);

    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    config.mtl_search_path = std::filesystem::path(objPath).parent_path().string();
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(objPath, config))
        throw InputError(objPath + ": " +
                         (reader.Error().empty() ? "cannot be read" : reader.Error()));

    const tinyobj::attrib_t& attrib = reader.GetAttrib();
    const auto& materials = reader.GetMaterials();

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
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
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
                    std::fprintf(stderr, "note: %s: faces without a material are grey (Kd 0.5)\n",
                                 objPath.c_str());
                }
                material = defaultMaterial;
            }
            scene.triangles.push_back(tri);
            scene.triangleMaterials.push_back(material);
        }
    }
    if (degenerate > 0)
        std::fprintf(stderr, "note: %s: skipped %d triangle(s) with zero area\n", objPath.c_str(),
                     degenerate);
}

} // namespace pathlab
