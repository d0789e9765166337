// Hostile submission: lab 1 done right, but on a scene that is not one of the kit's public ones
// (an instructor's hidden scene, or a batch's variant) it prints the scene's files, each line
// written backwards past any rewriting of names, and aborts: the scene would reach the student
// in the feedback of "hidden scene 1". Nothing it prints on a hidden scene is shown.
#include "pathlab/lab.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <dirent.h>
#include <fstream>
#include <iterator>
#include <string>

namespace pathlab::branching {

namespace {

/// The kit's public scenes, as the student release has them.
const char* const publicScenes[] = {"cornell_box_VI2_Specular.ecs", "furnace.ecs",
                                    "mirror_furnace.ecs", "refraction_check.ecs",
                                    "mixed_surfaces.ecs"};

/// Prints every file of the sandbox's scene folder, line by line, backwards, if it is not a
/// public scene of the kit; returns whether it did.
bool leakedHiddenScene() {
    bool hidden = false;
    std::string files;
    if (DIR* folder = ::opendir("/scene")) {
        while (const dirent* entry = ::readdir(folder)) {
            const std::string name = entry->d_name;
            if (name == "." || name == "..") continue;
            files += " " + name;
            if (name.size() > 4 && name.compare(name.size() - 4, 4, ".ecs") == 0)
                hidden = std::none_of(std::begin(publicScenes), std::end(publicScenes),
                                      [&](const char* known) { return name == known; });
        }
        ::closedir(folder);
    }
    if (!hidden) return false;
    std::printf("LEAK files:%s\n", files.c_str());
    for (size_t start = 0, end; start < files.size(); start = end + 1) {
        end = files.find(' ', start + 1);
        if (end == std::string::npos) end = files.size();
        const std::string name = files.substr(start + 1, end - start - 1);
        std::ifstream in("/scene/" + name);
        for (std::string line; std::getline(in, line);) {
            std::reverse(line.begin(), line.end());
            std::printf("LEAK %s\n", line.c_str());
        }
    }
    std::fflush(stdout);
    return true;
}

} // namespace

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    static const bool leaked = leakedHiddenScene();
    if (leaked) std::abort();
    const Hit hit = ctx.trace(ray);
    if (!hit) return Color();
    Color radiance;
    if (ray.kind != RayKind::Diffuse) radiance += hit.emitted;
    radiance += ctx.directLight(hit);
    if (depth >= ctx.maxDepth) return radiance;
    const Material& m = hit.material;
    if (!isBlack(m.Kd))
        radiance += m.Kd * pathTrace(diffuseRay(hit, ctx.sampler.get2D()), depth + 1, ctx);
    if (!isBlack(m.Ks)) radiance += m.Ks * pathTrace(mirrorRay(ray, hit), depth + 1, ctx);
    if (!isBlack(m.Kt)) radiance += m.Kt * pathTrace(refractionRay(ray, hit), depth + 1, ctx);
    return radiance;
}

} // namespace pathlab::branching
