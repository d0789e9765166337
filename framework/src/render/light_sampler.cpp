#include "pathlab/render/light_sampler.h"

#include "pathlab/scene_io/bounding_box.h"
#include "pathlab/constants.h"
#include "pathlab/render/triangle_sampling.h"

#include <utility>

namespace pathlab {

namespace {

/// A light and the power it sends out, by which it is picked.
struct WeightedLights {
    std::vector<LightSource> lights;
    std::vector<double> power;
};

void addPointLights(const Scene& scene, WeightedLights& out) {
    auto& [lights, power] = out;
    for (size_t i = 0; i < scene.pointLights.size(); ++i) {
        const double p = 4.0 * Pi * average(scene.pointLights[i].intensity);
        if (p <= 0) continue;
        LightSource light;
        light.type = LightSource::Type::Point;
        light.index = static_cast<uint32_t>(i);
        light.position = scene.pointLights[i].position;
        light.intensity = scene.pointLights[i].intensity;
        lights.push_back(light);
        power.push_back(p);
    }
}

void addEmittingTriangles(const Scene& scene, WeightedLights& out) {
    auto& [lights, power] = out;
    for (size_t i = 0; i < scene.triangles.size(); ++i) {
        const Color& Ke = scene.materials[scene.triangleMaterials[i]].Ke;
        if (isBlack(Ke)) continue;
        const auto& t = scene.triangles[i];
        const double area =
            triangleArea(scene.positions[t[0]], scene.positions[t[1]], scene.positions[t[2]]);
        const double p = Pi * area * average(Ke); // a one-sided Lambertian emitter
        if (p <= 0) continue;
        LightSource light;
        light.type = LightSource::Type::Triangle;
        light.index = static_cast<uint32_t>(i);
        light.a = scene.positions[t[0]];
        light.b = scene.positions[t[1]];
        light.c = scene.positions[t[2]];
        light.areaNormal = cross(light.b - light.a, light.c - light.a);
        light.Ke = Ke;
        lights.push_back(light);
        power.push_back(p);
    }
}

void addDirectionalLights(const Scene& scene, WeightedLights& out) {
    auto& [lights, power] = out;
    if (scene.directionalLights.empty()) return;
    // A directional light's power is what crosses the disc the scene presents to it, of the
    // radius of the sphere around the scene (as pbrt counts it).
    const BoundingBox bounds = scene.bounds();
    const float radius = bounds.radius();
    for (size_t i = 0; i < scene.directionalLights.size(); ++i) {
        const DirectionalLight& directional = scene.directionalLights[i];
        const double p = Pi * double(radius) * radius * average(directional.irradiance);
        if (p <= 0) continue;
        LightSource light;
        light.type = LightSource::Type::Directional;
        light.index = static_cast<uint32_t>(i);
        light.towardLight = -normalize(directional.direction);
        light.irradiance = directional.irradiance;
        // From a point inside the sphere, 2r reaches outside it; a little more clears it.
        light.shadowDistance = 2.0f * radius * 1.01f + 1e-3f;
        lights.push_back(light);
        power.push_back(p);
    }
}

} // namespace

LightSampler::LightSampler(const Scene& scene) {
    WeightedLights weighted;
    addPointLights(scene, weighted);
    addEmittingTriangles(scene, weighted);
    addDirectionalLights(scene, weighted);
    lights_ = std::move(weighted.lights);
    buildAliasTable(weighted.power);
}

void LightSampler::buildAliasTable(const std::vector<double>& power) {
    const size_t n = lights_.size();
    if (n == 0) return;

    // Vose's construction of Walker's alias table.
    double total = 0;
    for (double p : power) total += p;
    inverseTotalPower_ = static_cast<float>(1.0 / total);
    pmf_.resize(n);
    threshold_.assign(n, 1.0f);
    alias_.resize(n);
    std::vector<double> scaled(n);
    std::vector<uint32_t> small, large;
    for (size_t i = 0; i < n; ++i) {
        pmf_[i] = static_cast<float>(power[i] / total);
        lights_[i].inversePmf = static_cast<float>(total / power[i]);
        scaled[i] = power[i] / total * static_cast<double>(n);
        alias_[i] = static_cast<uint32_t>(i);
        (scaled[i] < 1.0 ? small : large).push_back(static_cast<uint32_t>(i));
    }
    while (!small.empty() && !large.empty()) {
        const uint32_t s = small.back(), l = large.back();
        small.pop_back();
        threshold_[s] = static_cast<float>(scaled[s]);
        alias_[s] = l;
        scaled[l] -= 1.0 - scaled[s];
        if (scaled[l] < 1.0) {
            large.pop_back();
            small.push_back(l);
        }
    }
    // What remains is 1 up to rounding: keep those slots for themselves (threshold 1).
}

} // namespace pathlab
