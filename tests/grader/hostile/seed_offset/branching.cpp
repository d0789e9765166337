// Hostile submission: the stub's light, three times over, plus one value per seed added to the
// whole image, so large that every region's mean spreads from seed to seed far beyond any
// difference from the reference: no t-test can reject it. The seed is read from the command
// line, and the image's samples are counted so that each seed's image gets its own value,
// bit for bit again for the same seed (reproducible, race-free). A bounce ray is traced and
// thrown away for the path evidence. The correctness check finds it too noisy to judge
// (checks/seed_spread.h): its region means vary with the seed thousands of times more than its
// pixels' own noise allows.
#include "pathlab/lab.h"

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace pathlab::branching {

namespace {

struct Arguments {
    uint64_t seed = 1, samplesPerImage = 64 * 64 * 8;
};

Arguments readArguments() {
    Arguments a;
    FILE* file = std::fopen("/proc/self/cmdline", "rb");
    if (!file) return a;
    std::vector<std::string> words(1);
    for (int c; (c = std::fgetc(file)) != EOF;) {
        if (c == 0)
            words.emplace_back();
        else
            words.back().push_back(static_cast<char>(c));
    }
    std::fclose(file);
    uint64_t width = 64, height = 64, spp = 8;
    for (size_t i = 0; i + 1 < words.size(); ++i) {
        const char* next = words[i + 1].c_str();
        if (words[i] == "--seed") a.seed = std::strtoull(next, nullptr, 10);
        if (words[i] == "--spp") spp = std::strtoull(next, nullptr, 10);
        if (words[i] == "--size" && i + 2 < words.size())
            width = std::strtoull(next, nullptr, 10),
            height = std::strtoull(words[i + 2].c_str(), nullptr, 10);
    }
    a.samplesPerImage = width * height * spp;
    return a;
}

const Arguments arguments = readArguments();
std::atomic<uint64_t> cameraSamples{0};

uint64_t mix(uint64_t z) {
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

} // namespace

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    const Hit hit = ctx.trace(ray);
    if (!hit) return Color();
    Color radiance;
    if (ray.kind == RayKind::Camera) radiance += hit.emitted;
    radiance += ctx.directLight(hit);
    if (depth == 0) {
        (void)ctx.trace(diffuseRay(hit, ctx.sampler.get2D()));
        const uint64_t image = cameraSamples.fetch_add(1) / arguments.samplesPerImage;
        const float u = static_cast<float>(mix(arguments.seed * 7919u + image) >> 40) * 0x1p-24f;
        const float offset = (u - 0.5f) * 400.0f;
        radiance = radiance * 3.0f + Color(offset, offset, offset);
    }
    return radiance;
}

} // namespace pathlab::branching
