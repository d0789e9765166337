#pragma once
/// Picks a light for next-event estimation in proportion to its power, in constant time.

#include "pathlab/color.h"
#include "pathlab/constants.h"
#include "pathlab/scene_io/scene.h"
#include "pathlab/vec3.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace pathlab {

/// One light of the scene: a point light, an emissive triangle or a directional light, with what
/// next-event estimation needs of it copied out of the Scene, so a shadow ray's setup reads one
/// record. Aligned to 32 bytes, which makes it 128: a power of two, so that finding a light by
/// its index (pick(), size()) is a shift rather than a multiplication.
struct alignas(32) LightSource {
    enum class Type { Point, Triangle, Directional } type = Type::Point;
    uint32_t index = 0; ///< into Scene::pointLights, the triangle index, or into
                        ///< Scene::directionalLights
    Vec3 position;      ///< a point light's position
    Color intensity;    ///< a point light's intensity
    Vec3 a, b, c;       ///< a triangle's vertices, counter-clockwise
    Vec3 areaNormal;    ///< a triangle's cross(b - a, c - a): twice its area, out of its front
    Color Ke;           ///< a triangle's emitted radiance
    Vec3 towardLight;   ///< a directional light's unit direction back towards it
    Color irradiance;   ///< a directional light's irradiance on a surface facing it
    /// How far a directional light's shadow ray reaches: from anywhere in the scene to beyond
    /// the sphere around it.
    float shadowDistance = 0;
    /// 1 / the probability LightSampler::pick() returns this light: next-event estimation's
    /// weight, so that a shadow ray multiplies rather than divides.
    float inversePmf = 0;
};

/// Walker's alias method over the lights' powers: one table lookup and one comparison per pick.
class LightSampler {
public:
    explicit LightSampler(const Scene& scene);

    bool empty() const { return lights_.empty(); }
    size_t size() const { return lights_.size(); }

    /// A light chosen with probability proportional to its power (u, v uniform in [0,1)).
    /// `pmf` is that probability.
    const LightSource& pick(float u, float v, float& pmf) const {
        const size_t slot = std::min(static_cast<size_t>(u * lights_.size()), lights_.size() - 1);
        const size_t chosen = v < threshold_[slot] ? slot : alias_[slot];
        pmf = pmf_[chosen];
        return lights_[chosen];
    }

    /// The probability pick() returns light i.
    float pmf(size_t i) const { return pmf_[i]; }

    /// The density per unit area with which pick() and a uniform point on the picked triangle
    /// choose a point of an emitting triangle of radiance `Ke`: its pick probability
    /// π·area·average(Ke) / (total power) over its area. The area cancels, so the density needs
    /// no lookup of which triangle was hit (ctx.lightPdf, lab 6).
    float trianglePointDensity(const Color& Ke) const {
        return Pi * average(Ke) * inverseTotalPower_;
    }
    const LightSource& light(size_t i) const { return lights_[i]; }

private:
    /// Vose's construction of Walker's alias table, each light in proportion to its power.
    void buildAliasTable(const std::vector<double>& power);

    std::vector<LightSource> lights_;
    std::vector<float> pmf_;
    std::vector<float> threshold_;
    std::vector<uint32_t> alias_;
    float inverseTotalPower_ = 0;
};

} // namespace pathlab
