#pragma once
/// The scene as loaded from files: triangles, materials, lights and camera, before Embree.

#include "pathlab/scene_io/bounding_box.h"
#include "pathlab/scene_io/camera.h"
#include "pathlab/color.h"
#include "pathlab/material.h"
#include "pathlab/vec3.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace pathlab {

/// An isotropic point light: intensity I (W/sr per channel), so the irradiance at distance r
/// facing it is I/r².
struct PointLight {
    Vec3 position;
    Color intensity;
};

/// A directional light as Embree's --dirlight gives it: light travelling along `direction` (not
/// necessarily unit length), with irradiance E (W/m² per channel) on a surface facing it.
struct DirectionalLight {
    Vec3 direction;
    Color irradiance;
};

/// All geometry merged into one indexed triangle mesh (one Embree geometry), so a hit's
/// primitive index is the triangle index below.
struct Scene {
    std::vector<Vec3> positions;     ///< vertex positions
    std::vector<Vec3> vertexNormals; ///< per vertex; the zero vector where the OBJ gave none
    std::vector<std::array<uint32_t, 3>> triangles; ///< vertex indices, counter-clockwise = front
    std::vector<uint32_t> triangleMaterials;        ///< index into `materials`, per triangle
    std::vector<Material> materials;
    std::vector<std::string> materialNames; ///< same order as `materials`
    std::vector<PointLight> pointLights;
    std::vector<DirectionalLight> directionalLights;
    std::optional<CameraSettings> camera; ///< from the scene script, if it set one

    /// Adds a material and returns its index.
    uint32_t addMaterial(const std::string& name, const Material& material) {
        materials.push_back(material);
        materialNames.push_back(name);
        return static_cast<uint32_t>(materials.size() - 1);
    }

    /// The box around the vertices the triangles use (an OBJ may list vertices no face uses,
    /// even at 1e+10); the unit cube around the origin when there are no triangles.
    BoundingBox bounds() const;

    /// A camera that frames the whole scene from the front (pathlab/scene_io/scene_defaults.h), for
    /// scenes without one.
    CameraSettings framingCamera() const;
};

} // namespace pathlab
