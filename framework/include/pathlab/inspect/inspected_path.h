#pragma once
/// What the path inspector shows of one pixel: each sample's path, vertex by vertex, with the
/// values the lab received and the weights it gave them (pathlab/inspect/pixel_inspector.h makes
/// it).

#include "pathlab/color.h"
#include "pathlab/material.h"
#include "pathlab/ray.h"
#include "pathlab/render/ray_log.h"
#include "pathlab/render/render_identity.h"
#include "pathlab/vec3.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace pathlab {

/// How the path went on from a vertex: one ray (a branching lab may send several).
struct PathContinuation {
    int child = -1;        ///< the vertex the ray found
    std::string component; ///< diffuse, mirror, refraction; specular when mirror and refraction
                           ///< are the same ray (total internal reflection); unknown for a ray the
                           ///< lab made itself
    /// What the lab divided the ray's weight by: the component's strength (Kd, Ks or Kt, in its
    /// strongest channel) over the weight the lab gave the ray. In lab 4 it includes
    /// continueProb. Unknown when a throughput could not be measured.
    std::optional<float> probability;
    /// Another component whose colour the lab weighted the ray by ("Kt" for a mirror ray given
    /// Kt's weight), when the weight is exactly that colour and not the ray's own component's:
    /// then `probability` is no division the lab made. Empty otherwise.
    std::string weightedBy;
};

/// Russian roulette at a vertex, for a lab that uses continueProb: the lab's first random number
/// at the vertex, and whether a ray went on from it.
struct RouletteDraw {
    float draw = 0;
    float continueProb = 0;
    bool wentOn = false;
};

/// One trace() of a sample's path and what it found.
struct InspectedVertex {
    int index = 0;
    int parent = -1;       ///< the vertex the ray left; -1 for the camera ray
    int depth = 0;         ///< bounces before it: 0 for the camera ray's hit
    std::string arrivedBy; ///< camera, or a continuation's component
    Ray ray;
    bool found = false; ///< false: the ray left the scene, and nothing below is meaningful
    Vec3 position;
    Material material;
    Color emitted; ///< what the hit carried as `hit.emitted`
    /// The weight the lab gave light found at this vertex: its throughput, measured on the
    /// direct light (or, where the lab called no directLight, on the emission). Unknown when
    /// neither was measurable.
    std::optional<Color> throughput;
    /// Whether the sample's value is linear in the direct light found here (measured with two
    /// sizes of change): where it is not (a clamp), `throughput` is no weight the lab gave.
    bool linear = true;
    std::optional<Color> emissionWeight; ///< the weight of `emitted` in the sample (0: not added)
    Color emissionAdded;                 ///< emissionWeight × emitted
    bool directLightCalled = false;
    Color directLight;      ///< what directLight() returned
    Color directLightAdded; ///< throughput × directLight
    std::optional<ShadowSegment> shadowRay;
    std::vector<float> draws; ///< the lab's own random numbers at this vertex
    std::vector<PathContinuation> continuedBy;
    std::optional<RouletteDraw> roulette;
};

/// One call the lab made, as the replay comparison reads it: trace, light or end, the vertex,
/// and the random numbers the lab drew before it.
struct InspectedCall {
    std::string type; ///< trace, light, end
    int vertex = -1;
    std::vector<float> drawsBefore;
};

struct InspectedSample {
    uint64_t index = 0; ///< the sample's number within its pixel, as the render numbers them
    Color contribution; ///< what pathTrace returned
    std::vector<InspectedVertex> vertices;
    std::vector<InspectedCall> calls;
};

/// A pixel's first samples through one lab.
struct PixelInspection {
    /// The render the pixel belongs to. Its JSON (inspection_json.h) keeps the lab, whose code,
    /// the parameters and the seed, not the size: read back, the size is the default.
    RenderIdentity identity;
    int x = 0, y = 0;
    /// The lab ends paths by roulette (a lab the lab list calls unbiased: lab 4), so each
    /// vertex's roulette draw is reported.
    bool usesRoulette = false;
    std::vector<InspectedSample> samples;
};

} // namespace pathlab
