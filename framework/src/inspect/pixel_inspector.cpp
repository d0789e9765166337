#include "pathlab/inspect/pixel_inspector.h"

#include "pathlab/scene_io/camera.h"
#include "pathlab/render/path_driver.h"
#include "pathlab/render/path_recorder.h"
#include "pathlab/render/ray_origin.h"
#include "pathlab/render/render_progress.h"
#include "pathlab/render/render_scene.h"
#include "pathlab/scattering.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace pathlab {

namespace {

/// One run of a sample's path, as recorded.
struct Replay {
    Color contribution;
    std::vector<PathEvent> events;
    std::vector<Ray> rays;
    std::vector<Hit> hits;
    std::vector<std::optional<RecordedDirectLight>> directLights;
};

class SampleReplayer {
public:
    SampleReplayer(const RenderScene& scene, const Camera& camera, PathTraceFunction pathTrace,
                   const InspectionRequest& request)
        : scene_(scene), camera_(camera), pathTrace_(pathTrace), request_(request) {}

    /// The sample as a render draws it: the pixel's jitter first, then the lab's path.
    Replay run(uint64_t sample, PathProbe probe) const {
        PathDriver driver(scene_, request_.identity.parameters);
        const auto pixel =
            static_cast<uint64_t>(request_.y) * static_cast<uint64_t>(request_.identity.width) +
            static_cast<uint64_t>(request_.x);
        driver.startSample(request_.identity.seed, pixel, sample);
        const Vec2 jitter = driver.context().sampler.get2D();
        const Ray cameraRay = camera_.generateRay(static_cast<float>(request_.x) + jitter.x,
                                                  static_cast<float>(request_.y) + jitter.y);
        PathRecorder recorder(probe, driver.context().sampler);
        driver.recordPathInto(&recorder);
        const Color contribution = pathTrace_(cameraRay, 0, driver.context());
        driver.recordPathInto(nullptr);
        recorder.ended(driver.context().sampler);
        if (request_.progress) request_.progress->add(1);
        return {contribution, recorder.events(), recorder.rays(), recorder.hits(),
                recorder.directLights()};
    }

private:
    const RenderScene& scene_;
    const Camera& camera_;
    PathTraceFunction pathTrace_;
    const InspectionRequest& request_;
};

template <typename T> bool sameBits(const T& a, const T& b) {
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

bool sameRay(const Ray& a, const Ray& b) {
    return sameBits(a.origin, b.origin) && sameBits(a.direction, b.direction) && a.kind == b.kind;
}

/// Whether a probed replay made the calls the first run made: only then does the change of its
/// value measure a weight (a lab that tests the changed value may have gone another way).
bool sameCalls(const Replay& a, const Replay& b) {
    if (a.events.size() != b.events.size() || a.rays.size() != b.rays.size()) return false;
    for (size_t i = 0; i < a.events.size(); ++i)
        if (a.events[i].type != b.events[i].type || a.events[i].vertex != b.events[i].vertex ||
            a.events[i].drawsBefore.size() != b.events[i].drawsBefore.size())
            return false;
    for (size_t i = 0; i < a.rays.size(); ++i)
        if (!sameRay(a.rays[i], b.rays[i])) return false;
    return true;
}

/// The weight the lab gives `actual`, from a replay in which it received PathProbe::changed.
std::optional<Color> measuredWeight(const SampleReplayer& replayer, uint64_t sample,
                                    const Replay& base, PathProbe probe, const Color& actual) {
    const Replay probed = replayer.run(sample, probe);
    if (!sameCalls(base, probed)) return std::nullopt;
    const Color given = PathProbe::changed(actual, probe.scale) - actual; // no channel is 0
    const Color change = probed.contribution - base.contribution;
    return Color{change.r / given.r, change.g / given.g, change.b / given.b};
}

/// Whether the lab's value is linear in the light given at a vertex: the weight measured with
/// a change 16 times smaller agrees with `weight` to 1% (float rounding stays far below that
/// for a weight above 1e-8). A clamp on the light a bounce returns fails it.
bool linearAt(const SampleReplayer& replayer, uint64_t sample, const Replay& base, PathProbe probe,
              const Color& actual, const Color& weight) {
    probe.scale = PathProbe::DefaultScale / 16;
    const std::optional<Color> smaller = measuredWeight(replayer, sample, base, probe, actual);
    if (!smaller) return true; // other calls at this scale: nothing to compare
    const auto agrees = [](float a, float b) {
        return std::fabs(a - b) <= 1e-2f * std::max(std::fabs(a), std::fabs(b)) + 1e-12f;
    };
    return agrees(weight.r, smaller->r) && agrees(weight.g, smaller->g) &&
           agrees(weight.b, smaller->b);
}

/// The vertex a ray left, and which of the framework's rays from there it is: a bounce ray's
/// origin and direction are those diffuseRay, mirrorRay, refractionRay or glossyRay make from the
/// hit.
void findParent(const Replay& replay, InspectedVertex& vertex) {
    const Ray& ray = vertex.ray;
    if (ray.kind == RayKind::Camera) {
        vertex.arrivedBy = "camera";
        return;
    }
    for (int u = vertex.index - 1; u >= 0; --u) {
        const Hit& from = replay.hits[static_cast<size_t>(u)];
        if (!from.found) continue;
        const Ray& incoming = replay.rays[static_cast<size_t>(u)];
        // A diffuse or glossy ray's direction comes from its numbers: its origin tells its parent.
        if (ray.kind == RayKind::Diffuse || ray.kind == RayKind::Glossy) {
            if (!sameBits(offsetRayOrigin(from, ray.direction), ray.origin)) continue;
            vertex.parent = u;
            vertex.arrivedBy = ray.kind == RayKind::Diffuse ? "diffuse" : "glossy";
            return;
        }
        const bool mirror = sameRay(mirrorRay(incoming, from), ray);
        const bool refraction = sameRay(refractionRay(incoming, from), ray);
        if (!mirror && !refraction) continue;
        vertex.parent = u;
        vertex.arrivedBy = mirror && refraction ? "specular" : mirror ? "mirror" : "refraction";
        return;
    }
    // A ray the lab made itself: the nearest hit before it, if one is near its origin.
    float nearest = INFINITY;
    for (int u = vertex.index - 1; u >= 0; --u) {
        const Hit& from = replay.hits[static_cast<size_t>(u)];
        if (!from.found) continue;
        const Vec3 offset = ray.origin - from.position;
        const float distance2 = dot(offset, offset);
        const float scale = 1e-3f * (1.0f + maxAbsComponent(from.position));
        if (distance2 < nearest && distance2 < scale * scale) {
            nearest = distance2;
            vertex.parent = u;
        }
    }
    vertex.arrivedBy = "unknown";
}

const Color* componentStrength(const Material& m, const std::string& component) {
    if (component == "diffuse") return &m.Kd;
    if (component == "mirror") return &m.Ks;
    if (component == "refraction") return &m.Kt;
    if (component == "specular") {
        // Total internal reflection: the same ray either way; the strength is unambiguous only
        // when the surface has one of the two.
        if (isBlack(m.Kt)) return &m.Ks;
        if (isBlack(m.Ks)) return &m.Kt;
    }
    return nullptr;
}

/// What the lab divided a ray's weight by: the strength of its component over the ratio of
/// the throughputs after and before it, in the component's strongest channel.
std::optional<float> dividedBy(const InspectedVertex& from, const InspectedVertex& to) {
    const Color* strength = componentStrength(from.material, to.arrivedBy);
    if (!strength || !from.throughput || !to.throughput) return std::nullopt;
    const int channel = strength->r >= strength->g && strength->r >= strength->b ? 0
                        : strength->g >= strength->b                             ? 1
                                                                                 : 2;
    const auto pick = [channel](const Color& c) {
        return channel == 0 ? c.r : channel == 1 ? c.g : c.b;
    };
    const float after = pick(*to.throughput);
    if (after == 0 || pick(*strength) == 0) return std::nullopt;
    return pick(*strength) * pick(*from.throughput) / after;
}

/// The other component (Kd, Ks or Kt, not the ray's own) whose colour the ray's weight equals
/// in every channel, where the ray's own component's colour differs from it: a mirror ray
/// weighted by Kt, say. Empty when there is none, or the throughputs cannot tell.
std::string weightedByOther(const InspectedVertex& from, const InspectedVertex& to) {
    const Color* own = componentStrength(from.material, to.arrivedBy);
    if (!own || !from.throughput || !to.throughput) return "";
    const auto same = [](float a, float b) {
        return std::fabs(a - b) <= 1e-4f * std::max(std::fabs(a), std::fabs(b));
    };
    const Color& before = *from.throughput;
    const Color& after = *to.throughput;
    if (!(before.r > 0 && before.g > 0 && before.b > 0)) return "";
    const Color weight{after.r / before.r, after.g / before.g, after.b / before.b};
    const auto equal = [&](const Color& c) {
        return same(weight.r, c.r) && same(weight.g, c.g) && same(weight.b, c.b);
    };
    if (equal(*own)) return "";
    const Material& m = from.material;
    const std::pair<const char*, const Color*> others[] = {
        {"Kd", &m.Kd}, {"Ks", &m.Ks}, {"Kt", &m.Kt}};
    for (const auto& [name, colour] : others)
        if (colour != own && !isBlack(*colour) && equal(*colour)) return name;
    return "";
}

const char* callType(PathEvent::Type type) {
    switch (type) {
    case PathEvent::Type::Trace: return "trace";
    case PathEvent::Type::DirectLight: return "light";
    case PathEvent::Type::End: return "end";
    }
    return "end";
}

InspectedSample inspectSample(const SampleReplayer& replayer, const InspectionRequest& request,
                              uint64_t sampleIndex) {
    const Replay base = replayer.run(sampleIndex, {});
    InspectedSample sample;
    sample.index = sampleIndex;
    sample.contribution = base.contribution;
    auto& vertices = sample.vertices;
    for (size_t i = 0; i < base.rays.size(); ++i) {
        InspectedVertex vertex;
        vertex.index = static_cast<int>(i);
        vertex.ray = base.rays[i];
        const Hit& hit = base.hits[i];
        vertex.found = hit.found;
        vertex.position = hit.position;
        vertex.material = hit.material;
        vertex.emitted = hit.emitted;
        findParent(base, vertex);
        if (vertex.parent >= 0)
            vertex.depth = vertices[static_cast<size_t>(vertex.parent)].depth + 1;
        if (hit.found) {
            if (const auto& light = base.directLights[i]) {
                vertex.directLightCalled = true;
                vertex.directLight = light->value;
                if (light->sentShadowRay) vertex.shadowRay = light->shadowRay;
                const PathProbe probe{PathProbe::Value::DirectLight, vertex.index};
                vertex.throughput =
                    measuredWeight(replayer, sampleIndex, base, probe, light->value);
                if (vertex.throughput)
                    vertex.linear = linearAt(replayer, sampleIndex, base, probe, light->value,
                                             *vertex.throughput);
            }
            vertex.emissionWeight =
                measuredWeight(replayer, sampleIndex, base,
                               {PathProbe::Value::Emission, vertex.index}, hit.emitted);
            if (!vertex.throughput && vertex.emissionWeight && !isBlack(*vertex.emissionWeight))
                vertex.throughput = vertex.emissionWeight;
            if (vertex.emissionWeight) vertex.emissionAdded = *vertex.emissionWeight * hit.emitted;
            if (vertex.throughput)
                vertex.directLightAdded = *vertex.throughput * vertex.directLight;
        }
        vertices.push_back(vertex);
    }
    // The lab's draws belong to the vertex it drew them at: before a ray, the vertex the ray
    // leaves; before directLight, the vertex lit; before the end, the last vertex called on.
    int current = -1;
    for (const PathEvent& event : base.events) {
        int owner = current;
        if (event.type == PathEvent::Type::Trace)
            owner = vertices[static_cast<size_t>(event.vertex)].parent;
        else if (event.type == PathEvent::Type::DirectLight)
            owner = event.vertex;
        if (owner >= 0) {
            auto& draws = vertices[static_cast<size_t>(owner)].draws;
            draws.insert(draws.end(), event.drawsBefore.begin(), event.drawsBefore.end());
        }
        if (event.vertex >= 0) current = event.vertex;
        sample.calls.push_back({callType(event.type), event.vertex, event.drawsBefore});
    }
    for (InspectedVertex& vertex : vertices) {
        if (vertex.parent < 0) continue;
        InspectedVertex& from = vertices[static_cast<size_t>(vertex.parent)];
        // A weight measured where the lab is not linear is no weight: nothing is said of it.
        if (!vertex.linear || !from.linear)
            from.continuedBy.push_back({vertex.index, vertex.arrivedBy, std::nullopt, ""});
        else
            from.continuedBy.push_back({vertex.index, vertex.arrivedBy, dividedBy(from, vertex),
                                        weightedByOther(from, vertex)});
    }
    if (!isDepthLimited(request.identity.lab))
        for (InspectedVertex& vertex : vertices)
            if (vertex.found && !vertex.draws.empty())
                vertex.roulette =
                    RouletteDraw{vertex.draws.front(), request.identity.parameters.continueProb,
                                 !vertex.continuedBy.empty()};
    return sample;
}

} // namespace

PixelInspection inspectPixel(const RenderScene& scene, const Camera& camera,
                             PathTraceFunction pathTrace, const InspectionRequest& request) {
    const SampleReplayer replayer(scene, camera, pathTrace, request);
    PixelInspection inspection;
    inspection.identity = request.identity;
    inspection.x = request.x;
    inspection.y = request.y;
    inspection.usesRoulette = !isDepthLimited(request.identity.lab);
    for (int s = 0; s < request.samples; ++s)
        inspection.samples.push_back(inspectSample(replayer, request, static_cast<uint64_t>(s)));
    return inspection;
}

} // namespace pathlab
