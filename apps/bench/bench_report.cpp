#include "bench_report.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <thread>

namespace pathlab::bench {

namespace {

using nlohmann::json;

double rate(size_t count, double seconds) {
    return seconds > 0 ? count / seconds : 0;
}

/// "12.3M": millions with three significant digits.
std::string millions(double perSecond) {
    char text[32];
    const double m = perSecond / 1e6;
    std::snprintf(text, sizeof text, m >= 100 ? "%.0fM" : (m >= 10 ? "%.1fM" : "%.2fM"), m);
    return text;
}

void printScene(const SceneFigures& s, std::FILE* out) {
    std::fprintf(out,
                 "\n%s: %zu triangles, %dx%d, %d spp per pass, fastest of %d passes, %d threads, "
                 "max-depth %d, continue-prob %g\n",
                 s.name.c_str(), s.triangles, s.width, s.height, s.spp, s.passes, s.threads,
                 s.parameters.maxDepth, s.parameters.continueProb);

    const TraversalTimes one = s.rawOneThread(), all = s.raw();
    std::fprintf(out, "\n  Embree alone (the solutions' rays, replayed)   1 thread  %2d threads\n",
                 s.threads);
    std::fprintf(out, "    camera rays (coherent flag), rays/s       %9s  %10s\n",
                 millions(rate(one.cameraRays, one.cameraSeconds)).c_str(),
                 millions(rate(all.cameraRays, all.cameraSeconds)).c_str());
    std::fprintf(out, "    closest-hit rays (incoherent), rays/s     %9s  %10s\n",
                 millions(rate(one.bounceRays, one.bounceSeconds)).c_str(),
                 millions(rate(all.bounceRays, all.bounceSeconds)).c_str());
    std::fprintf(out, "    occlusion rays, rays/s                    %9s  %10s\n",
                 millions(rate(one.shadowRays, one.shadowSeconds)).c_str(),
                 millions(rate(all.shadowRays, all.shadowSeconds)).c_str());

    std::fprintf(
        out,
        "\n  reference   %2d threads: samples/s intersect/s occluded/s  rays/s  Embree-alone"
        " efficiency | 1 thread: samples/s efficiency | scaling\n",
        s.threads);
    for (const SolutionFigures& f : s.solutions) {
        std::fprintf(out, "  %-10s %22s %11s %10s %7s %13s %10.2f | %19s %10.2f | %6.2fx\n",
                     std::string(labName(f.lab)).c_str(),
                     millions(f.render.samplesPerSecond()).c_str(),
                     millions(f.render.intersectPerSecond()).c_str(),
                     millions(f.render.occludedPerSecond()).c_str(),
                     millions(f.render.raysPerSecond()).c_str(), millions(f.raw.mixRate()).c_str(),
                     f.efficiency(), millions(f.renderOneThread.samplesPerSecond()).c_str(),
                     f.efficiencyOneThread(), f.scaling());
    }
    std::fprintf(
        out, "  (efficiency: the rays/s achieved over Embree's rate for the same rays alone)\n");
}

void printPeer(const PeerComparison& c, std::FILE* out) {
    if (!c.measured) {
        std::fprintf(out, "\nEmbree's pathtracer: %s\n", c.note.c_str());
        return;
    }
    std::fprintf(out,
                 "\nEmbree's pathtracer on %s (point lights x%g), %dx%d, %d spp per frame, "
                 "fastest of %d frames, %d threads,\n  path length %d = PathLab's importance "
                 "solution at max-depth %d\n",
                 c.scene.c_str(), c.lightScale, c.width, c.height, c.spp, c.frames, c.threads,
                 c.maxPathLength, c.maxPathLength - 1);
    std::fprintf(out,
                 "                            samples/s   mean radiance at %d spp, 8-bit as "
                 "Embree stores it\n",
                 c.imageSpp);
    std::fprintf(out, "    Embree pathtracer     %11s   %.5f %.5f %.5f\n",
                 millions(c.embreeSamplesPerSecond).c_str(), c.embreeMean.r, c.embreeMean.g,
                 c.embreeMean.b);
    std::fprintf(out, "    PathLab importance    %11s   %.5f %.5f %.5f\n",
                 millions(c.oursSamplesPerSecond).c_str(), c.oursMean.r, c.oursMean.g,
                 c.oursMean.b);
    const Color d = c.oursMean - c.embreeMean;
    if (c.imageSpp > 1) {
        std::fprintf(out,
                     "    PathLab / Embree      %10.2fx   difference in standard errors: %.1f "
                     "%.1f %.1f\n",
                     c.ratio(), d.r / c.standardError.r, d.g / c.standardError.g,
                     d.b / c.standardError.b);
    } else {
        std::fprintf(out,
                     "    PathLab / Embree      %10.2fx   (one sample per pixel: no standard "
                     "error)\n",
                     c.ratio());
    }
    std::fprintf(out, "    (PathLab's largest pixel value %.3f: %s)\n", c.oursMaxPixel,
                 c.oursMaxPixel < 1 ? "nothing clipped" : "CLIPPED, dim the light");
}

void printMemory(const MemoryFigures& m, std::FILE* out) {
    if (!m.measured) {
        std::fprintf(out, "\nPeak memory: %s\n", m.note.c_str());
        return;
    }
    std::fprintf(out,
                 "\nPeak memory of a progressive render (the window's render path, no window), "
                 "%dx%d, %d frames: %.0f MiB\n",
                 m.width, m.height, m.frames, m.peakMiB);
}

json rgb(const Color& c) {
    return json::array({c.r, c.g, c.b});
}

json rawJson(const TraversalTimes& t) {
    return {
        {"camera", rate(t.cameraRays, t.cameraSeconds)},
        {"closest_hit", rate(t.bounceRays, t.bounceSeconds)},
        {"occlusion", rate(t.shadowRays, t.shadowSeconds)},
        {"rays",
         {{"camera", t.cameraRays}, {"closest_hit", t.bounceRays}, {"occlusion", t.shadowRays}}}};
}

json renderJson(const RenderTiming& r) {
    return {{"samples_per_second", r.samplesPerSecond()},
            {"rays_per_second",
             {{"intersect", r.intersectPerSecond()},
              {"occluded", r.occludedPerSecond()},
              {"total", r.raysPerSecond()}}}};
}

json sceneJson(const SceneFigures& s) {
    json solutions = json::array();
    for (const SolutionFigures& f : s.solutions) {
        json one = renderJson(f.renderOneThread);
        one["raw_mix_rays_per_second"] = f.rawOneThread.mixRate();
        one["efficiency"] = f.efficiencyOneThread();
        json all = renderJson(f.render);
        all["raw_mix_rays_per_second"] = f.raw.mixRate();
        all["efficiency"] = f.efficiency();
        solutions.push_back({{"lab", labName(f.lab)},
                             {"threads", all},
                             {"one_thread", one},
                             {"efficiency", f.efficiency()},
                             {"scaling", f.scaling()}});
    }
    return {{"scene", s.name},
            {"triangles", s.triangles},
            {"width", s.width},
            {"height", s.height},
            {"spp", s.spp},
            {"passes", s.passes},
            {"threads", s.threads},
            {"max_depth", s.parameters.maxDepth},
            {"continue_prob", s.parameters.continueProb},
            {"raw", {{"one_thread", rawJson(s.rawOneThread())}, {"threads", rawJson(s.raw())}}},
            {"solutions", solutions}};
}

json peerJson(const PeerComparison& c) {
    if (!c.measured) return {{"measured", false}, {"note", c.note}};
    return {{"measured", true},
            {"scene", c.scene},
            {"light_scale", c.lightScale},
            {"width", c.width},
            {"height", c.height},
            {"spp", c.spp},
            {"frames", c.frames},
            {"threads", c.threads},
            {"max_path_length", c.maxPathLength},
            {"max_depth", c.maxPathLength - 1},
            {"embree_samples_per_second", c.embreeSamplesPerSecond},
            {"ours_samples_per_second", c.oursSamplesPerSecond},
            {"ratio", c.ratio()},
            {"image_spp", c.imageSpp},
            {"mean_radiance", {{"embree", rgb(c.embreeMean)}, {"ours", rgb(c.oursMean)}}},
            {"standard_error", rgb(c.standardError)},
            {"ours_max_pixel", c.oursMaxPixel}};
}

json memoryJson(const MemoryFigures& m) {
    if (!m.measured) return {{"measured", false}, {"note", m.note}};
    return {{"measured", true},
            {"width", m.width},
            {"height", m.height},
            {"frames", m.frames},
            {"peak_mib", m.peakMiB}};
}

} // namespace

void printReport(const BenchReport& report, std::FILE* out) {
    for (const SceneFigures& s : report.scenes)
        printScene(s, out);
    printPeer(report.peer, out);
    printMemory(report.memory, out);
}

std::string reportJson(const BenchReport& report) {
    json scenes = json::array();
    for (const SceneFigures& s : report.scenes)
        scenes.push_back(sceneJson(s));
    const json document = {{"pathlab_version", PATHLAB_VERSION},
                           {"cores", std::thread::hardware_concurrency()},
                           {"scenes", scenes},
                           {"embree_pathtracer", peerJson(report.peer)},
                           {"memory", memoryJson(report.memory)}};
    return document.dump(2) + "\n";
}

} // namespace pathlab::bench
