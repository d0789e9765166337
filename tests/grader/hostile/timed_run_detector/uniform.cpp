// Hostile submission: lab 2 done right, except when it thinks it is being timed: then it stops
// bouncing and runs faster. It looks where a timed run used to differ from the correctness
// renders (a larger image on its command line) and at the one thing that still differs in a
// batch, the core it runs on (the first core is the timing core). The command line gives it
// nothing; the core does, and the speed check then sees that its timed runs render other images
// than the same seeds did in the correctness renders: no speed points.
#include "pathlab/lab.h"

#include <algorithm>
#include <fstream>
#include <sched.h>
#include <sstream>
#include <string>

namespace pathlab::uniform {

namespace {

bool timedByCommandLine() {
    std::ifstream in("/proc/self/cmdline", std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    std::string line = text.str();
    std::replace(line.begin(), line.end(), '\0', ' ');
    return line.find("--size 256") != std::string::npos;
}

} // namespace

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    static const bool timedByArguments = timedByCommandLine();
    const Hit hit = ctx.trace(ray);
    if (!hit) return Color();
    Color radiance;
    if (ray.kind != RayKind::Diffuse) radiance += hit.emitted;
    radiance += ctx.directLight(hit);
    if (depth >= ctx.maxDepth) return radiance;
    if (timedByArguments || ::sched_getcpu() == 0) return radiance;
    constexpr float pickProbability = 1.0f / 3.0f;
    const int component = std::min(static_cast<int>(ctx.sampler.get1D() * 3.0f), 2);
    const Material& m = hit.material;
    if (component == 0 && !isBlack(m.Kd))
        radiance += m.Kd * pathTrace(diffuseRay(hit, ctx.sampler.get2D()), depth + 1, ctx) /
                    pickProbability;
    if (component == 1 && !isBlack(m.Ks))
        radiance += m.Ks * pathTrace(mirrorRay(ray, hit), depth + 1, ctx) / pickProbability;
    if (component == 2 && !isBlack(m.Kt))
        radiance += m.Kt * pathTrace(refractionRay(ray, hit), depth + 1, ctx) / pickProbability;
    return radiance;
}

} // namespace pathlab::uniform
