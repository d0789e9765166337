#pragma once
/// The path inspector's record of one sample: every trace() and directLight() a lab made, in
/// order, with the random numbers the lab drew between them; and the probe that changes one value
/// the lab receives, to measure the weight the lab gives it.

#include "pathlab/color.h"
#include "pathlab/hit.h"
#include "pathlab/random_stream.h"
#include "pathlab/ray.h"
#include "pathlab/render/ray_log.h"
#include "pathlab/sampler.h"

#include <optional>
#include <vector>

#ifdef PATHLAB_IMPL
#error "pathlab/render/path_recorder.h is the path inspector's: a lab includes pathlab/lab.h only"
#endif

namespace pathlab {

/// Which value a replay changes: the emission a trace() finds at one vertex, or what
/// directLight() returns there. Everything a lab computes from them is linear in them, so the
/// change of the sample's contribution, divided by the change of the value, is the lab's weight
/// of that value: its throughput at the vertex (pixel_inspector.cpp).
struct PathProbe {
    enum class Value { None, Emission, DirectLight };
    Value value = Value::None;
    int vertex = -1; ///< the trace() that found the vertex, counted from 0

    /// How large the change is: the weight is measured at the default scale, and again at a
    /// smaller one to tell whether the lab is linear in the light at all (a clamp is not).
    static constexpr float DefaultScale = 65536;
    float scale = DefaultScale;

    /// What the lab receives instead of `actual`: each channel 1 + `scale` times as large, or
    /// `scale` where it is 0. A colour that was not black stays so; a black one does not, and
    /// the replay checks that the lab then made the same calls.
    static Color changed(const Color& actual, float scale = DefaultScale);
};

/// One call a lab made, in the order made.
struct PathEvent {
    enum class Type { Trace, DirectLight, End };
    Type type = Type::End;
    int vertex = -1;                ///< the vertex the trace found or directLight lit; End: -1
    std::vector<float> drawsBefore; ///< the lab's own random numbers since the previous event
};

/// What directLight() returned at a vertex, before any probe.
struct RecordedDirectLight {
    Color value;
    bool sentShadowRay = false;
    ShadowSegment shadowRay; ///< when one was sent
};

class PathRecorder {
public:
    /// A path is cut off after this many trace() calls: a lab that never stops would otherwise
    /// hang the inspector.
    static constexpr size_t MaxRays = 100000;

    explicit PathRecorder(PathProbe probe, const Sampler& start);

    /// A trace() call: records it and returns what the lab receives.
    Hit traced(const Ray& ray, Hit hit, const Sampler& now);
    /// A directLight() call, whose own random numbers lie between `before` and `after`.
    Color directLit(const Hit& hit, Color light, bool sentShadowRay, const Sampler& before,
                    const Sampler& after);
    /// A sampleLight() call (lab 6), whose own random numbers lie between `before` and
    /// `after`: they are the framework's, and the lab's draws before it count toward its next
    /// event. (Its light is not probed: the inspector measures weights by trace and directLight.)
    void sampledLight(const Sampler& before, const Sampler& after);
    /// pathTrace returned.
    void ended(const Sampler& now);

    /// Where directLight() logs its shadow ray while recorded.
    RayLog& shadowRays() { return shadowRays_; }

    const std::vector<PathEvent>& events() const { return events_; }
    /// The rays traced and what they found (before a probe), vertex by vertex.
    const std::vector<Ray>& rays() const { return rays_; }
    const std::vector<Hit>& hits() const { return hits_; }
    /// What directLight() returned at each vertex, where the lab called it.
    const std::vector<std::optional<RecordedDirectLight>>& directLights() const {
        return directLights_;
    }

private:
    std::vector<float> drawsSince(const Sampler& now);
    int vertexOf(const Hit& hit) const;

    PathProbe probe_;
    RandomStream stream_; ///< where the lab's random numbers stood at the last call
    std::vector<float>
        pendingDraws_; ///< the lab's draws before a sampleLight(), for the next event
    std::vector<PathEvent> events_;
    std::vector<Ray> rays_;
    std::vector<Hit> hits_;
    std::vector<std::optional<RecordedDirectLight>> directLights_;
    RayLog shadowRays_;
};

} // namespace pathlab
