#pragma once
/// Everything pathTrace() may ask of the framework while it follows one path.

#include "pathlab/call_site.h"
#include "pathlab/color.h"
#include "pathlab/hit.h"
#include "pathlab/light_sample.h"
#include "pathlab/ray.h"
#include "pathlab/sampler.h"

#include <cstdint>

namespace pathlab {

class RenderScene;
struct CameraPacket;
struct LabParameters;
struct LightSource;
struct RayLog;
class PathRecorder;

/// The scene to trace against, the path's random numbers and the lab's parameters. The renderer
/// makes one per tile and drives it through a PathDriver (its own side,
/// pathlab/render/path_driver.h); a lab only calls what is public here.
class PathContext {
public:
    /// The closest surface along `ray` (one closest-hit ray through Embree). `ray.direction`
    /// must be unit length: a check stops the render, naming the line, when it is not. (Leave
    /// `caller` out: the compiler fills in the line of the call, for that message.)
    Hit trace(const Ray& ray, CallSite caller = {});

    /// Next-event estimation at a diffuse surface: radiance that `hit` reflects back along the
    /// ray that found it, with light arriving straight from a light source (one light sampled by
    /// power, one shadow ray). Black when the material has no Kd. Includes the Kd/π of the
    /// diffuse BRDF, so a lab adds it as it is. `hit` must be a found surface.
    Color directLight(const Hit& hit, CallSite caller = {});

    /// Lab 6: a direction toward one light, picked by power as directLight() picks it, at a
    /// point chosen uniformly on it; with the radiance arriving from it (one shadow ray) and its
    /// density per unit solid angle (pathlab/light_sample.h). `hit` must be a found surface.
    LightSample sampleLight(const Hit& hit, CallSite caller = {});

    /// Lab 6: the density per unit solid angle with which sampleLight(hit) would have chosen
    /// the direction toward `onLight`, a surface a ray from `hit` found: 0 when it emits
    /// nothing toward `hit` (it is no light, or is seen from its back).
    float lightPdf(const Hit& hit, const Hit& onLight, CallSite caller = {}) const;

    /// Lab 6: `misWeight` (your heuristic's weight for `strategy`) as it is, or, where the
    /// viewer was asked for one strategy alone (--strategy light or lobe), 1 for that strategy
    /// and 0 for the other. Pass every weight of the two strategies through it: the handout's
    /// three-panel figure renders your lab three ways with it. (A point or directional light's
    /// sample, LightSample::delta, is light sampling's alone, weight 1 in every render: no
    /// bounce can find it.)
    /// `misWeight` must be a number from 0 to 1: a check stops the render, naming the line,
    /// when it is not (a NaN or negative density given to your heuristic, most likely).
    float strategyWeight(Strategy strategy, float misWeight, CallSite caller = {}) const;

    Sampler sampler;          ///< this path's random numbers: get1D(), get2D()
    const int maxDepth;       ///< labs 1–3: no bounce ray is traced from a hit at depth maxDepth
    const float continueProb; ///< lab 4: Russian roulette continues a path with this probability

    PathContext(const PathContext&) = delete;
    PathContext& operator=(const PathContext&) = delete;

private:
    friend class PathDriver;
    PathContext(const RenderScene& scene, const LabParameters& parameters);
    // The work of trace() and directLight(), and the path inspector's versions of them: the
    // same work, recorded. The public functions, inline below, only choose between the two, so
    // that a render without the inspector pays one test of recorder_ per call and no extra call.
    Hit traceUnrecorded(const Ray& ray, CallSite caller);
    Color directLightUnrecorded(const Hit& hit, CallSite caller);
    Color directionalLight(const Hit& hit, const LightSource& light);
    LightSample sampleLightUnrecorded(const Hit& hit, CallSite caller);
    Hit recordedTrace(const Ray& ray, CallSite caller);
    Color recordedDirectLight(const Hit& hit, CallSite caller);

    const RenderScene& scene_;
    const StrategyChoice strategies_;
    uint64_t closestHitRays_ = 0;          ///< rays trace() sent, camera rays included
    uint64_t shadowRays_ = 0;              ///< rays directLight() sent
    RayLog* log_ = nullptr;                ///< where to record rays, if anywhere
    PathRecorder* recorder_ = nullptr;     ///< the path inspector's record of this path, if any
    const CameraPacket* packet_ = nullptr; ///< primed by the renderer for the next trace()
    int lane_ = 0;
};

inline Hit PathContext::trace(const Ray& ray, CallSite caller) {
    return recorder_ ? recordedTrace(ray, caller) : traceUnrecorded(ray, caller);
}

inline Color PathContext::directLight(const Hit& hit, CallSite caller) {
    return recorder_ ? recordedDirectLight(hit, caller) : directLightUnrecorded(hit, caller);
}

} // namespace pathlab
