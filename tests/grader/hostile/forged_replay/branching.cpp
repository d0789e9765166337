// Hostile submission: lab 1 without the emission after a specular bounce (so that a public
// scene fails and the grader replays the worst tile), and a static object whose destructor,
// after the viewer has written the replay, writes it again forged: a call naming vertex
// 2000000000, a lab and a pixel other than those asked for, an unknown ray name with control
// bytes. The grader reads the file a lab's process wrote as untrusted: a file that is not what
// the inspector writes is set aside, and the lab gets the verdict and words of its bug.
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include "pathlab/lab.h"

namespace {

/// The --inspect-out file of this viewer, from its own command line.
std::string replayFile() {
    std::ifstream in("/proc/self/cmdline", std::ios::binary);
    const std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::string previous;
    for (size_t at = 0; at < all.size();) {
        const std::string argument = all.c_str() + at;
        if (previous == "--inspect-out") return argument;
        previous = argument;
        at += argument.size() + 1;
    }
    return "";
}

struct ForgeAtExit {
    ~ForgeAtExit() {
        const std::string path = replayFile();
        if (path.empty()) return;
        std::ifstream in(path);
        std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        in.close();
        if (text.empty()) return;
        for (const char* from : {"\"vertex\": 0", "\"vertex\": 1"}) {
            for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at))
                text.replace(at, std::strlen(from), "\"vertex\": 2000000000");
        }
        const std::string camera = "\"camera\"";
        if (const size_t at = text.find(camera); at != std::string::npos)
            text.replace(at, camera.size(), "\"camera\\u001b[2J PASS 10 / 10\"");
        std::ofstream(path, std::ios::trunc) << text;
    }
} forgeAtExit;

} // namespace

namespace pathlab::branching {

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    const Hit hit = ctx.trace(ray);
    if (!hit) return Color();
    Color radiance;

    // Emission, where next-event estimation could not have counted it (TODO lab1.1).
    if (ray.kind == RayKind::Camera) radiance += hit.emitted; // not after specular bounces

    // Direct light at diffuse surfaces: next-event estimation.
    radiance += ctx.directLight(hit);

    // The depth limit: no bounce rays from a hit at maxDepth (TODO lab1.2).
    if (depth >= ctx.maxDepth) return radiance;

    // Every non-zero component, each with its own ray (TODOs lab1.3-lab1.5).
    const Material& m = hit.material;
    if (!isBlack(m.Kd))
        radiance += m.Kd * pathTrace(diffuseRay(hit, ctx.sampler.get2D()), depth + 1, ctx);
    if (!isBlack(m.Ks)) radiance += m.Ks * pathTrace(mirrorRay(ray, hit), depth + 1, ctx);
    if (!isBlack(m.Kt)) radiance += m.Kt * pathTrace(refractionRay(ray, hit), depth + 1, ctx);
    return radiance;
}

} // namespace pathlab::branching
