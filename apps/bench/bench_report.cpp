#include "bench_report.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <thread>

namespace pathlab::bench {

namespace {

using nlohmann::json;

double rate(size_t count, double seconds) { return seconds > 0 ? count / seconds : 0; }

/// "12.3M": millions with three significant digits.
std::string millions(double perSecond) {
    char text[32];
    const double m = perSecond / 1e6;
    std::snprintf(text, sizeof text, m >= 100 ? "%.0fM" : (m >= 10 ? "%.1fM" : "%.2fM"), m);
    return text;
}

void printScene(const SceneFigures& s, std::FILE* out) {
    std::fprintf(out,
                 "\n%s: %zu triangles, %dx%d, %d spp per pass, fastest of %d passes, max-depth "
                 "%d, continue-prob %g\n",
                 s.name.c_str(), s.triangles, s.settings.width, s.settings.height, s.settings.spp,
                 s.settings.passes, s.settings.parameters.maxDepth,
                 s.settings.parameters.continueProb);

    const TraversalTimes one = s.rawOneThread(), all = s.raw();
    std::fprintf(out,
                 "\n  Embree alone, on the rays the solutions traced   1 thread  %2d threads\n",
                 s.settings.threads);
    const auto rawRow = [&](const char* what, size_t rays1, double seconds1, size_t raysN,
                            double secondsN) {
        std::fprintf(out, "    %-30s rays/s  %9s  %10s\n", what,
                     millions(rate(rays1, seconds1)).c_str(),
                     millions(rate(raysN, secondsN)).c_str());
    };
    rawRow("camera rays (coherent)", one.cameraRays, one.cameraSeconds, all.cameraRays,
           all.cameraSeconds);
    rawRow("closest-hit rays (incoherent)", one.bounceRays, one.bounceSeconds, all.bounceRays,
           all.bounceSeconds);
    rawRow("occlusion rays", one.shadowRays, one.shadowSeconds, all.shadowRays, all.shadowSeconds);

    std::fprintf(out, "\n  solution    threads  samples/s  intersect/s  occluded/s   rays/s  "
                      "Embree alone  efficiency\n");
    const auto solutionRow = [&](const char* lab, int threads, const RenderTiming& r,
                                 const TraversalTimes& raw, double efficiency) {
        std::fprintf(out, "  %-10s %8d %10s %12s %11s %8s %13s %11.2f\n", lab, threads,
                     millions(r.samplesPerSecond()).c_str(),
                     millions(r.intersectPerSecond()).c_str(),
                     millions(r.occludedPerSecond()).c_str(), millions(r.raysPerSecond()).c_str(),
                     millions(raw.mixRate()).c_str(), efficiency);
    };
    for (const SolutionFigures& f : s.solutions) {
        const std::string lab(labName(f.lab));
        solutionRow(lab.c_str(), 1, f.renderOneThread, f.rawOneThread, f.efficiencyOneThread());
        solutionRow("", s.settings.threads, f.render, f.raw, f.efficiency());
    }
    std::fprintf(out, "  efficiency: rays/s achieved / Embree's rays/s on the same rays alone\n");
    std::fprintf(out, "  thread scaling, samples/s with %d threads / 1:", s.settings.threads);
    for (const SolutionFigures& f : s.solutions)
        std::fprintf(out, "  %s %.2fx", std::string(labName(f.lab)).c_str(), f.scaling());
    std::fprintf(out, "\n");
}

/// One line per path length under a header that says what was compared: samples/s of each,
/// their ratio, and the two images' means, 8-bit as Embree stores them.
void printPeers(const std::vector<PeerComparison>& peers, std::FILE* out) {
    const auto measured = std::find_if(peers.begin(), peers.end(),
                                       [](const PeerComparison& c) { return c.measured; });
    if (measured == peers.end()) {
        std::fprintf(out, "\nEmbree's pathtracer: %s\n",
                     peers.empty() ? "no path length asked for" : peers.front().note.c_str());
        return;
    }
    const PeerComparison& h = *measured;
    std::fprintf(out,
                 "\nEmbree's pathtracer on %s (point lights x%g), %dx%d, %d spp per frame, "
                 "%d threads,\n  fastest of %d rounds of %d frames each, taken in turn; path "
                 "length L = PathLab's importance\n  solution at max-depth L-1; mean radiance at "
                 "%d spp, 8-bit as Embree stores it\n",
                 h.scene.c_str(), h.lightScale, h.width, h.height, h.spp, h.threads, h.rounds,
                 h.frames, h.imageSpp);
    std::fprintf(out, "  path length  Embree samples/s  PathLab samples/s  PathLab / Embree   "
                      "mean radiance: Embree, PathLab           difference (standard errors)\n");
    for (const PeerComparison& c : peers) {
        if (!c.measured) {
            std::fprintf(out, "  %11d  %s\n", c.maxPathLength, c.note.c_str());
            continue;
        }
        std::fprintf(out, "  %11d  %16s  %17s  %15.2fx   %.5f %.5f %.5f, %.5f %.5f %.5f",
                     c.maxPathLength, millions(c.embreeSamplesPerSecond).c_str(),
                     millions(c.oursSamplesPerSecond).c_str(), c.ratio(), c.embreeMean.r,
                     c.embreeMean.g, c.embreeMean.b, c.oursMean.r, c.oursMean.g, c.oursMean.b);
        const Color d = c.oursMean - c.embreeMean;
        if (c.imageSpp > 1)
            std::fprintf(out, "   %.1f %.1f %.1f\n", d.r / c.standardError.r,
                         d.g / c.standardError.g, d.b / c.standardError.b);
        else
            std::fprintf(out, "   (1 spp: no standard error)\n");
    }
    float brightest = 0;
    for (const PeerComparison& c : peers)
        if (c.measured) brightest = std::max(brightest, c.oursMaxPixel);
    std::fprintf(out, "  (PathLab's largest pixel value %.3f: %s)\n", brightest,
                 brightest < 1 ? "nothing clipped" : "CLIPPED, dim the light");
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

void printScaling(const ScalingFigures& f, std::FILE* out) {
    std::fprintf(out,
                 "\nScaling: %s solution on %s, %dx%d, 1 spp per pass as the window renders, "
                 "fastest of %d passes\n  threads       ",
                 std::string(labName(f.lab)).c_str(), f.scene.c_str(), f.width, f.height, f.passes);
    for (const ScalingFigures::Point& p : f.byThreads) std::fprintf(out, "%9d", p.value);
    std::fprintf(out, "\n  samples/s     ");
    for (const ScalingFigures::Point& p : f.byThreads)
        std::fprintf(out, "%9s", millions(p.samplesPerSecond).c_str());
    std::fprintf(out, "\n  tile size     ");
    for (const ScalingFigures::Point& p : f.byTileSize) std::fprintf(out, "%9d", p.value);
    std::fprintf(out, "   (%d threads)\n  tiles         ", f.tileThreads);
    for (const ScalingFigures::Point& p : f.byTileSize)
        std::fprintf(out, "%9d",
                     ((f.width + p.value - 1) / p.value) * ((f.height + p.value - 1) / p.value));
    std::fprintf(out, "\n  samples/s     ");
    for (const ScalingFigures::Point& p : f.byTileSize)
        std::fprintf(out, "%9s", millions(p.samplesPerSecond).c_str());
    std::fprintf(out,
                 "\n  the window's hand-off between frames (the image's figures and its copy for "
                 "display): %.2f ms,\n  %.0f%% of a frame at %d threads; were the passes to scale "
                 "on, %.0f%% at 16 threads, %.0f%% at 64\n",
                 f.handOffSeconds * 1e3, 100 * f.handOffShare(f.tileThreads), f.tileThreads,
                 100 * f.handOffShare(16), 100 * f.handOffShare(64));
}

json scalingJson(const ScalingFigures& f) {
    json threads = json::array(), tiles = json::array();
    for (const ScalingFigures::Point& p : f.byThreads)
        threads.push_back({{"threads", p.value}, {"samples_per_second", p.samplesPerSecond}});
    for (const ScalingFigures::Point& p : f.byTileSize)
        tiles.push_back({{"tile_size", p.value}, {"samples_per_second", p.samplesPerSecond}});
    return {{"scene", f.scene},
            {"solution", labName(f.lab)},
            {"width", f.width},
            {"height", f.height},
            {"by_threads", threads},
            {"tile_threads", f.tileThreads},
            {"by_tile_size", tiles},
            {"hand_off_ms", f.handOffSeconds * 1e3},
            {"hand_off_share", f.handOffShare(f.tileThreads)},
            {"hand_off_share_at_64_threads", f.handOffShare(64)}};
}

void printFirstFrame(const FirstFrameLatency& f, std::FILE* out) {
    if (!f.measured) {
        std::fprintf(out, "\nThe viewer's first frame: %s\n", f.note.c_str());
        return;
    }
    std::fprintf(
        out,
        "\nThe viewer's window under Xvfb, %dx%d, importance solution, median of %d "
        "starts:\n  start to first frame %.0f ms, start to first image on screen %.0f ms\n",
        f.width, f.height, f.runs, f.firstFrameMs, f.firstImageMs);
}

json rgb(const Color& c) { return json::array({c.r, c.g, c.b}); }

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
            {"width", s.settings.width},
            {"height", s.settings.height},
            {"spp", s.settings.spp},
            {"passes", s.settings.passes},
            {"threads", s.settings.threads},
            {"max_depth", s.settings.parameters.maxDepth},
            {"continue_prob", s.settings.parameters.continueProb},
            {"raw", {{"one_thread", rawJson(s.rawOneThread())}, {"threads", rawJson(s.raw())}}},
            {"solutions", solutions}};
}

json peerJson(const PeerComparison& c) {
    if (!c.measured)
        return {{"measured", false}, {"note", c.note}, {"max_path_length", c.maxPathLength}};
    return {{"measured", true},
            {"scene", c.scene},
            {"light_scale", c.lightScale},
            {"width", c.width},
            {"height", c.height},
            {"spp", c.spp},
            {"frames", c.frames},
            {"rounds", c.rounds},
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

json firstFrameJson(const FirstFrameLatency& f) {
    if (!f.measured) return {{"measured", false}, {"note", f.note}};
    return {{"measured", true},
            {"runs", f.runs},
            {"width", f.width},
            {"height", f.height},
            {"first_frame_ms", f.firstFrameMs},
            {"first_image_ms", f.firstImageMs}};
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
    for (const SceneFigures& s : report.scenes) printScene(s, out);
    printPeers(report.peers, out);
    for (const ScalingFigures& f : report.scaling) printScaling(f, out);
    printFirstFrame(report.firstFrame, out);
    printMemory(report.memory, out);
}

std::string reportJson(const BenchReport& report) {
    json scenes = json::array();
    for (const SceneFigures& s : report.scenes) scenes.push_back(sceneJson(s));
    json peers = json::array();
    for (const PeerComparison& c : report.peers) peers.push_back(peerJson(c));
    json scaling = json::array();
    for (const ScalingFigures& f : report.scaling) scaling.push_back(scalingJson(f));
    const json document = {{"pathlab_version", PATHLAB_VERSION},
                           {"cores", std::thread::hardware_concurrency()},
                           {"scenes", scenes},
                           {"embree_pathtracer", peers},
                           {"scaling", scaling},
                           {"first_frame", firstFrameJson(report.firstFrame)},
                           {"memory", memoryJson(report.memory)}};
    return document.dump(2) + "\n";
}

} // namespace pathlab::bench
