#pragma once
/// The renderer's side of a PathContext: what a lab must not reach.

#include "pathlab/render/camera_packet.h"
#include "pathlab/path_context.h"
#include "pathlab/random_stream.h"
#include "pathlab/render/ray_counters.h"
#include "pathlab/render/ray_log.h"

#include <cstdint>

// Lab files are compiled with PATHLAB_IMPL (student or solution): they see lab.h and nothing of
// the renderer's side.
#ifdef PATHLAB_IMPL
#error                                                                                             \
    "pathlab/render/path_driver.h is the renderer's side of PathContext: a lab includes pathlab/lab.h only"
#endif

namespace pathlab {

/// Owns the PathContext a lab's pathTrace receives and does for the renderer what the student
/// API leaves out: restarting each sample's random numbers, handing over a camera ray already
/// traced in a packet, counting and recording rays. (pbrt keeps its pixel loop beside the one
/// function an integrator writes in the same way.)
class PathDriver {
public:
    PathDriver(const RenderScene& scene, const LabParameters& parameters)
        : ctx_(scene, parameters) {}

    /// What pathTrace is given.
    PathContext& context() { return ctx_; }

    /// Where the random numbers of a pixel's sample 0 begin: a hash of the seed and the pixel,
    /// made once per pixel. Sample k's begin SampleStride·k further on.
    static uint64_t pixelStreamStart(uint64_t seed, uint64_t pixelIndex) {
        return mix64(mix64(seed) ^ pixelIndex);
    }
    /// How far apart one pixel's samples start: 2^32 draws, more than any path takes, so their
    /// numbers never overlap.
    static constexpr uint64_t SampleStride = StreamGamma << 32;
    /// The random numbers of one sample of one pixel, the same wherever and whenever it is
    /// rendered.
    static Sampler samplerFor(uint64_t seed, uint64_t pixelIndex, uint64_t sampleIndex) {
        return samplerAt(pixelStreamStart(seed, pixelIndex), sampleIndex);
    }
    /// The same, from the pixel's pixelStreamStart: all a sample costs is this multiply-add.
    static Sampler samplerAt(uint64_t pixelStart, uint64_t sampleIndex) {
        return Sampler(RandomStream(pixelStart + sampleIndex * SampleStride));
    }
    /// Restarts the context's random numbers for one sample of one pixel.
    void startSample(uint64_t seed, uint64_t pixelIndex, uint64_t sampleIndex) {
        restoreSampler(samplerFor(seed, pixelIndex, sampleIndex));
    }
    /// The same, from the pixel's pixelStreamStart.
    void startSampleAt(uint64_t pixelStart, uint64_t sampleIndex) {
        restoreSampler(samplerAt(pixelStart, sampleIndex));
    }
    /// The context's random numbers where they are now, to take up again with restoreSampler.
    Sampler savedSampler() const { return ctx_.sampler; }
    void restoreSampler(const Sampler& saved) { ctx_.sampler.rng_ = saved.rng_; }

    /// Hands the next trace() the hit of the camera ray in `lane` of a traced packet: the
    /// renderer traces camera rays in packets, and a lab's first trace() is that ray. (Any
    /// other ray is traced as usual.)
    void primeCameraHit(const CameraPacket* packet, int lane) {
        ctx_.packet_ = packet;
        ctx_.lane_ = lane;
    }
    /// Also appends every ray traced from now on to `log` (null: stop recording).
    void recordRaysInto(RayLog* log) { ctx_.log_ = log; }
    /// Records every call of trace() and directLight() from now on in `recorder` (null: stop),
    /// for the path inspector (pathlab/inspect/pixel_inspector.h). A render that records nothing
    /// pays one untaken branch per call.
    void recordPathInto(PathRecorder* recorder) { ctx_.recorder_ = recorder; }
    /// Rays traced through the context so far.
    RayCounters rayCounters() const { return {ctx_.closestHitRays_, ctx_.shadowRays_}; }

private:
    PathContext ctx_;
};

} // namespace pathlab
