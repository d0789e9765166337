#include "pathlab/render/path_recorder.h"

#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>

namespace pathlab {

namespace {

/// A lab draws a handful of numbers per vertex; past this many between two calls the count is
/// given up (a draw loop of the lab's own), and the record starts again from the new position.
constexpr int MaxDrawsCounted = 4096;

bool samePosition(const Vec3& a, const Vec3& b) { return std::memcmp(&a, &b, sizeof(Vec3)) == 0; }

} // namespace

Color PathProbe::changed(const Color& actual, float scale) {
    // A large change: the sample's value is a float sum of everything the path found, and the
    // change must stand far above that sum's rounding even where the lab's weight is tiny (a
    // vertex 30 roulette bounces deep). Linear arithmetic is as exact at this scale as at 1.
    const auto channel = [scale](float value) { return value != 0 ? value * (1 + scale) : scale; };
    return {channel(actual.r), channel(actual.g), channel(actual.b)};
}

PathRecorder::PathRecorder(PathProbe probe, const Sampler& start)
    : probe_(probe), stream_(start.rng_) {}

std::vector<float> PathRecorder::drawsSince(const Sampler& now) {
    std::vector<float> draws = std::exchange(pendingDraws_, {});
    RandomStream stepping = stream_;
    while (!(stepping == now.rng_)) {
        if (draws.size() == MaxDrawsCounted) {
            stepping = now.rng_;
            break;
        }
        draws.push_back(stepping.nextFloat());
    }
    stream_ = stepping;
    return draws;
}

int PathRecorder::vertexOf(const Hit& hit) const {
    for (size_t i = hits_.size(); i-- > 0;)
        if (hits_[i].found && samePosition(hits_[i].position, hit.position))
            return static_cast<int>(i);
    return -1;
}

Hit PathRecorder::traced(const Ray& ray, Hit hit, const Sampler& now) {
    if (rays_.size() == MaxRays)
        throw std::runtime_error("the path traced more than " + std::to_string(MaxRays) +
                                 " rays: an endless loop, or recursion that never ends?");
    const int vertex = static_cast<int>(rays_.size());
    events_.push_back({PathEvent::Type::Trace, vertex, drawsSince(now)});
    rays_.push_back(ray);
    hits_.push_back(hit);
    directLights_.emplace_back();
    if (probe_.value == PathProbe::Value::Emission && probe_.vertex == vertex && hit.found) {
        // A lab may read the emission from the material as well as from the hit.
        hit.emitted = PathProbe::changed(hit.emitted, probe_.scale);
        hit.material.Ke = hit.emitted;
    }
    return hit;
}

Color PathRecorder::directLit(const Hit& hit, Color light, bool sentShadowRay,
                              const Sampler& before, const Sampler& after) {
    const int vertex = vertexOf(hit);
    events_.push_back({PathEvent::Type::DirectLight, vertex, drawsSince(before)});
    stream_ = after.rng_; // directLight's own draws are the framework's, not the lab's
    if (vertex >= 0 && !directLights_[static_cast<size_t>(vertex)]) {
        RecordedDirectLight recorded{light, sentShadowRay, {}};
        if (sentShadowRay) recorded.shadowRay = shadowRays_.occlusion.back();
        directLights_[static_cast<size_t>(vertex)] = recorded;
    }
    if (probe_.value == PathProbe::Value::DirectLight && probe_.vertex == vertex)
        return PathProbe::changed(light, probe_.scale);
    return light;
}

void PathRecorder::sampledLight(const Sampler& before, const Sampler& after) {
    pendingDraws_ = drawsSince(before);
    stream_ = after.rng_; // sampleLight's own draws are the framework's, not the lab's
}

void PathRecorder::ended(const Sampler& now) {
    events_.push_back({PathEvent::Type::End, -1, drawsSince(now)});
}

} // namespace pathlab
