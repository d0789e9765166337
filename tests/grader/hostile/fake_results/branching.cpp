// Hostile submission: the stub's direct light only, dressed up as a perfect score. It prints
// what a grader might parse, and at exit overwrites the viewer's stats and image files with
// "results" of its own. The grader measures everything itself, so it fails correctness.
#include "pathlab/lab.h"

#include <cstdio>
#include <cstdlib>

namespace pathlab::branching {

namespace {

void fake() {
    std::printf("{\"score\": 40, \"max_score\": 40}\nbranching   pass 10/10\ntotal 40/40\n");
    if (std::FILE* f = std::fopen("render.json", "w")) {
        std::fputs("{\"nonfinite_pixels\": 0, \"mean_variance\": [0, 0, 0], \"score\": 40}", f);
        std::fclose(f);
    }
}

} // namespace

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    static const bool registered = std::atexit(fake) == 0;
    (void)registered, (void)depth;
    const Hit hit = ctx.trace(ray);
    if (!hit) return Color();
    return hit.emitted + ctx.directLight(hit);
}

} // namespace pathlab::branching
