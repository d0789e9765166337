#pragma once
/// Everything pathTrace() may ask of the framework while it follows one path.

#include "pathlab/camera_packet.h"
#include "pathlab/color.h"
#include "pathlab/hit.h"
#include "pathlab/lab_parameters.h"
#include "pathlab/ray.h"
#include "pathlab/ray_counters.h"
#include "pathlab/ray_log.h"
#include "pathlab/sampler.h"

namespace pathlab {

class RenderScene;

/// The scene to trace against, the path's random numbers and the lab's parameters. The renderer
/// makes one per tile; a lab only calls it.
class PathContext {
public:
    PathContext(const RenderScene& scene, const LabParameters& parameters)
        : maxDepth(parameters.maxDepth), continueProb(parameters.continueProb), scene_(scene) {}

    /// The closest surface along `ray` (one closest-hit ray through Embree).
    Hit trace(const Ray& ray);

    /// Next-event estimation at a diffuse surface: radiance that `hit` reflects back along the
    /// ray that found it, with light arriving straight from a light source (one light sampled by
    /// power, one shadow ray). Black when the material has no Kd. Includes the Kd/π of the
    /// diffuse BRDF, so a lab adds it as it is.
    Color directLight(const Hit& hit);

    Sampler sampler;         ///< this path's random numbers: get1D(), get2D()
    const int maxDepth;      ///< labs 1–3: no bounce ray is traced from a hit at depth maxDepth
    const float continueProb; ///< lab 4: Russian roulette continues a path with this probability

    /// Rays traced through this context so far.
    const RayCounters& rayCounters() const { return counters_; }
    /// Also appends every ray traced from now on to `log` (null: stop recording).
    void recordRaysInto(RayLog* log) { log_ = log; }
    /// Hands the next trace() the hit of the camera ray in `lane` of a traced packet: the
    /// renderer traces camera rays in packets, and a lab's first trace() is that ray. (Any
    /// other ray is traced as usual.)
    void primeCameraHit(const CameraPacket* packet, int lane) {
        packet_ = packet;
        lane_ = lane;
    }

private:
    const RenderScene& scene_;
    RayCounters counters_;
    RayLog* log_ = nullptr;
    const CameraPacket* packet_ = nullptr; ///< primed by the renderer for the next trace()
    int lane_ = 0;
};

} // namespace pathlab
