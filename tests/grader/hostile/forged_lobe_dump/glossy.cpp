// Hostile submission: lab 5 with the stub's lobe (every direction the lobe's axis, a density of
// 1), and a static object whose destructor, after the viewer has written its --lobe-dump file,
// writes it again forged: "all exponents passed". The grader reads the file a lab's process wrote
// as untrusted numbers: one that is not the dump it asked for fails correctness, saying so.
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include "pathlab/lab.h"

namespace {

/// The --lobe-dump file of this viewer, from its own command line.
std::string dumpFile() {
    std::ifstream in("/proc/self/cmdline", std::ios::binary);
    const std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::string previous;
    for (size_t at = 0; at < all.size();) {
        const std::string argument = all.c_str() + at;
        if (previous == "--lobe-dump") return argument;
        previous = argument;
        at += argument.size() + 1;
    }
    return "";
}

struct ForgeAtExit {
    ~ForgeAtExit() {
        const std::string file = dumpFile();
        if (file.empty()) return;
        std::ofstream(file, std::ios::binary | std::ios::trunc) << "all exponents passed\n";
    }
} forge;

} // namespace

namespace pathlab::glossy {

Vec3 sampleLobe(Vec2, float) { return {0, 0, 1}; }

float lobePdf(Vec3, float) { return 1.0f; }

Color pathTrace(const Ray& ray, int, PathContext& ctx) {
    const Hit hit = ctx.trace(ray);
    if (!hit) return Color();
    return hit.emitted + ctx.directLight(hit);
}

} // namespace pathlab::glossy
