#include "bench_report.h"

#include "busy_machine.h"

#include "pathlab/support/cpu_clock.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
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

/// Under a table: a few lines if other programs shared the machine while it was measured,
/// broken between words to fit the tables' width.
void printBusyNote(const std::vector<CpuUse>& uses, std::FILE* out) {
    constexpr size_t Width = 96;
    std::string line;
    std::istringstream words(busyNote(uses));
    for (std::string word; words >> word;) {
        if (!line.empty() && line.size() + 1 + word.size() > Width) {
            std::fprintf(out, "  %s\n", line.c_str());
            line.clear();
        }
        line += (line.empty() ? "" : " ") + word;
    }
    if (!line.empty()) std::fprintf(out, "  %s\n", line.c_str());
}

/// What each timed run of a scene's table had of the machine.
std::vector<CpuUse> sceneCpuUse(const SceneFigures& s) {
    std::vector<CpuUse> uses;
    for (const SolutionFigures& f : s.solutions) {
        const std::string lab(labName(f.lab));
        const auto render = [&](const RenderTiming& r) {
            uses.push_back({lab + "'s passes on " + threadsText(r.threads), r.cpuSeconds, r.seconds,
                            r.threads});
        };
        const auto raw = [&](const TraversalTimes& t, int threads) {
            uses.push_back({"Embree alone on " + lab + "'s rays on " + threadsText(threads),
                            t.cpuSeconds(), t.seconds(), threads});
        };
        render(f.renderOneThread);
        render(f.render);
        raw(f.rawOneThread, 1);
        raw(f.raw, s.settings.threads);
    }
    return uses;
}

void printScene(const SceneFigures& s, std::FILE* out) {
    std::fprintf(out,
                 "\n%s: %zu triangles, %dx%d, %d spp per pass, the pass of least CPU time of %d, "
                 "max-depth %d, continue-prob %g\n",
                 s.name.c_str(), s.triangles, s.settings.width, s.settings.height, s.settings.spp,
                 s.settings.passes, s.settings.parameters.maxDepth,
                 s.settings.parameters.continueProb);

    // Per CPU-second, Embree's rate hardly depends on the threads (their CPU time is summed);
    // per wall second it grows with them.
    const TraversalTimes one = s.rawOneThread(), all = s.raw();
    std::fprintf(out,
                 "\n  Embree alone, on the rays the solutions traced   rays per CPU-second    "
                 "rays/s (wall clock)\n"
                 "                                                   1 thread  %2d threads    "
                 "1 thread  %2d threads\n",
                 s.settings.threads, s.settings.threads);
    const auto rawRow = [&](const char* what, size_t rays1, double cpu1, double seconds1,
                            size_t raysN, double cpuN, double secondsN) {
        std::fprintf(out, "    %-45s %9s  %10s   %9s  %10s\n", what,
                     millions(rate(rays1, cpu1)).c_str(), millions(rate(raysN, cpuN)).c_str(),
                     millions(rate(rays1, seconds1)).c_str(),
                     millions(rate(raysN, secondsN)).c_str());
    };
    rawRow("camera rays (coherent)", one.cameraRays, one.cameraCpuSeconds, one.cameraSeconds,
           all.cameraRays, all.cameraCpuSeconds, all.cameraSeconds);
    rawRow("closest-hit rays (incoherent)", one.bounceRays, one.bounceCpuSeconds, one.bounceSeconds,
           all.bounceRays, all.bounceCpuSeconds, all.bounceSeconds);
    rawRow("occlusion rays", one.shadowRays, one.shadowCpuSeconds, one.shadowSeconds,
           all.shadowRays, all.shadowCpuSeconds, all.shadowSeconds);

    std::fprintf(out, "\n                       per CPU-second                                   "
                      "             wall clock\n"
                      "  solution    threads   samples  intersect  occluded     rays  Embree alone"
                      "  efficiency    samples/s  efficiency\n");
    const auto solutionRow = [&](const char* lab, const RenderTiming& r, const TraversalTimes& raw,
                                 double efficiency, double wallClockEfficiency) {
        std::fprintf(
            out, "  %-10s %8d %9s %10s %9s %8s %13s %11.2f %12s %11.2f\n", lab, r.threads,
            millions(r.samplesPerCpuSecond()).c_str(), millions(r.intersectPerCpuSecond()).c_str(),
            millions(r.occludedPerCpuSecond()).c_str(), millions(r.raysPerCpuSecond()).c_str(),
            millions(raw.mixRatePerCpuSecond()).c_str(), efficiency,
            millions(r.samplesPerSecond()).c_str(), wallClockEfficiency);
    };
    for (const SolutionFigures& f : s.solutions) {
        const std::string lab(labName(f.lab));
        solutionRow(lab.c_str(), f.renderOneThread, f.rawOneThread, f.efficiencyOneThread(),
                    f.wallClockEfficiencyOneThread());
        solutionRow("", f.render, f.raw, f.efficiency(), f.wallClockEfficiency());
    }
    std::fprintf(out, "  efficiency: rays per CPU-second achieved / Embree's alone on the same "
                      "rays, the share of the\n  render's CPU time that is Embree's traversal; "
                      "wall clock: the same by wall time\n");
    std::fprintf(
        out, "  thread scaling (wall clock), samples/s with %d threads / 1:", s.settings.threads);
    for (const SolutionFigures& f : s.solutions)
        std::fprintf(out, "  %s %.2fx", std::string(labName(f.lab)).c_str(), f.scaling());
    std::fprintf(out, "\n");
    printBusyNote(sceneCpuUse(s), out);
}

/// What both tracers' threads had of the machine, at every path length measured.
std::vector<CpuUse> peerCpuUse(const std::vector<PeerComparison>& peers) {
    std::vector<CpuUse> uses;
    for (const PeerComparison& c : peers) {
        if (!c.measured) continue;
        uses.push_back(c.embreeCpuUse);
        uses.push_back(c.oursCpuUse);
    }
    return uses;
}

/// One line per path length under a header that says what was compared: samples per CPU-second
/// and per second of each and their ratios; then the two images' means, 8-bit as Embree stores
/// them.
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
                 "%d threads,\n  best of %d rounds of %d frames each, taken in turn; path "
                 "length L = PathLab's importance\n  solution at max-depth L-1; CPU time: each "
                 "process's per frame, Embree's from a run of %d frames\n  less one of none "
                 "(its start-up); wall clock: the fastest frame\n",
                 h.scene.c_str(), h.lightScale, h.width, h.height, h.spp, h.threads, h.rounds,
                 h.frames, h.frames);
    std::fprintf(out, "               samples per CPU-second              samples/s (wall clock)"
                      "              Embree's CPU time per frame\n"
                      "  path length     Embree    PathLab  PathLab / Embree     Embree    "
                      "PathLab  PathLab / Embree  by round (run of none)\n");
    for (const PeerComparison& c : peers) {
        if (!c.measured) {
            std::fprintf(out, "  %11d  %s\n", c.maxPathLength, c.note.c_str());
            continue;
        }
        char cpuRatio[32] = "-"; // Embree's frames too short to time by CPU (c.cpuNote)
        if (c.cpuRatio() > 0) std::snprintf(cpuRatio, sizeof cpuRatio, "%.2fx", c.cpuRatio());
        std::fprintf(out, "  %11d %10s %10s %17s %10s %10s %16.2fx  ", c.maxPathLength,
                     c.embreeSamplesPerCpuSecond > 0 ? millions(c.embreeSamplesPerCpuSecond).c_str()
                                                     : "-",
                     millions(c.oursSamplesPerCpuSecond).c_str(), cpuRatio,
                     millions(c.embreeSamplesPerSecond).c_str(),
                     millions(c.oursSamplesPerSecond).c_str(), c.ratio());
        for (double seconds : c.embreeCpuSecondsPerFrame) std::fprintf(out, "%.3g ", seconds);
        std::fprintf(out, "s (%.3g s)\n", c.embreeStartCpuSeconds);
    }
    for (const PeerComparison& c : peers)
        if (c.measured && !c.cpuNote.empty())
            std::fprintf(out, "  path length %d: %s\n", c.maxPathLength, c.cpuNote.c_str());
    printBusyNote(peerCpuUse(peers), out);

    std::fprintf(out,
                 "  path length  mean radiance at %d spp, 8-bit as Embree stores it: "
                 "Embree, PathLab   difference (standard errors)\n",
                 h.imageSpp);
    for (const PeerComparison& c : peers) {
        if (!c.measured) continue;
        std::fprintf(out, "  %11d  %.5f %.5f %.5f, %.5f %.5f %.5f", c.maxPathLength, c.embreeMean.r,
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

/// What the threads of each scaling run had of the machine.
std::vector<CpuUse> scalingCpuUse(const ScalingFigures& f) {
    std::vector<CpuUse> uses;
    for (const ScalingFigures::Point& p : f.byThreads)
        uses.push_back({"the passes on " + threadsText(p.value), p.timing.cpuSeconds,
                        p.timing.seconds, p.timing.threads});
    for (const ScalingFigures::Point& p : f.byTileSize)
        uses.push_back({"the passes in tiles of " + std::to_string(p.value), p.timing.cpuSeconds,
                        p.timing.seconds, p.timing.threads});
    return uses;
}

void printScaling(const ScalingFigures& f, std::FILE* out) {
    std::fprintf(out,
                 "\nScaling (wall clock: how soon a pass is done): %s solution on %s,\n  %dx%d, "
                 "1 spp per pass as the window renders, fastest of %d passes\n  threads       ",
                 std::string(labName(f.lab)).c_str(), f.scene.c_str(), f.width, f.height, f.passes);
    for (const ScalingFigures::Point& p : f.byThreads) std::fprintf(out, "%9d", p.value);
    std::fprintf(out, "\n  samples/s     ");
    for (const ScalingFigures::Point& p : f.byThreads)
        std::fprintf(out, "%9s", millions(p.samplesPerSecond()).c_str());
    std::fprintf(out, "\n  tile size     ");
    for (const ScalingFigures::Point& p : f.byTileSize) std::fprintf(out, "%9d", p.value);
    std::fprintf(out, "   (%d threads)\n  tiles         ", f.tileThreads);
    for (const ScalingFigures::Point& p : f.byTileSize)
        std::fprintf(out, "%9d",
                     ((f.width + p.value - 1) / p.value) * ((f.height + p.value - 1) / p.value));
    std::fprintf(out, "\n  samples/s     ");
    for (const ScalingFigures::Point& p : f.byTileSize)
        std::fprintf(out, "%9s", millions(p.samplesPerSecond()).c_str());
    std::fprintf(out,
                 "\n  the window's hand-off between frames (the image's figures and its copy for "
                 "display): %.2f ms,\n  %.0f%% of a frame at %d threads; were the passes to scale "
                 "on, %.0f%% at 16 threads, %.0f%% at 64\n",
                 f.handOffSeconds * 1e3, 100 * f.handOffShare(f.tileThreads), f.tileThreads,
                 100 * f.handOffShare(16), 100 * f.handOffShare(64));
    printBusyNote(scalingCpuUse(f), out);
}

json scalingJson(const ScalingFigures& f) {
    json threads = json::array(), tiles = json::array();
    for (const ScalingFigures::Point& p : f.byThreads)
        threads.push_back({{"threads", p.value}, {"samples_per_second", p.samplesPerSecond()}});
    for (const ScalingFigures::Point& p : f.byTileSize)
        tiles.push_back({{"tile_size", p.value}, {"samples_per_second", p.samplesPerSecond()}});
    return {{"scene", f.scene},
            {"solution", labName(f.lab)},
            {"width", f.width},
            {"height", f.height},
            {"by_threads", threads},
            {"tile_threads", f.tileThreads},
            {"by_tile_size", tiles},
            {"hand_off_ms", f.handOffSeconds * 1e3},
            {"hand_off_share", f.handOffShare(f.tileThreads)},
            {"hand_off_share_at_64_threads", f.handOffShare(64)},
            {"busy_note", busyNote(scalingCpuUse(f))}};
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
        {"camera_per_cpu_second", rate(t.cameraRays, t.cameraCpuSeconds)},
        {"closest_hit_per_cpu_second", rate(t.bounceRays, t.bounceCpuSeconds)},
        {"occlusion_per_cpu_second", rate(t.shadowRays, t.shadowCpuSeconds)},
        {"rays",
         {{"camera", t.cameraRays}, {"closest_hit", t.bounceRays}, {"occlusion", t.shadowRays}}}};
}

json renderJson(const RenderTiming& r) {
    return {{"samples_per_second", r.samplesPerSecond()},
            {"rays_per_second",
             {{"intersect", r.intersectPerSecond()},
              {"occluded", r.occludedPerSecond()},
              {"total", r.raysPerSecond()}}},
            {"samples_per_cpu_second", r.samplesPerCpuSecond()},
            {"rays_per_cpu_second",
             {{"intersect", r.intersectPerCpuSecond()},
              {"occluded", r.occludedPerCpuSecond()},
              {"total", r.raysPerCpuSecond()}}},
            {"cpu_share", CpuUse{"", r.cpuSeconds, r.seconds, r.threads}.share()}};
}

json sceneJson(const SceneFigures& s) {
    json solutions = json::array();
    for (const SolutionFigures& f : s.solutions) {
        json one = renderJson(f.renderOneThread);
        one["raw_mix_rays_per_second"] = f.rawOneThread.mixRate();
        one["raw_mix_rays_per_cpu_second"] = f.rawOneThread.mixRatePerCpuSecond();
        one["efficiency"] = f.efficiencyOneThread();
        one["efficiency_wall"] = f.wallClockEfficiencyOneThread();
        json all = renderJson(f.render);
        all["raw_mix_rays_per_second"] = f.raw.mixRate();
        all["raw_mix_rays_per_cpu_second"] = f.raw.mixRatePerCpuSecond();
        all["efficiency"] = f.efficiency();
        all["efficiency_wall"] = f.wallClockEfficiency();
        solutions.push_back({{"lab", labName(f.lab)},
                             {"threads", all},
                             {"one_thread", one},
                             {"efficiency", f.efficiency()},
                             {"efficiency_wall", f.wallClockEfficiency()},
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
            {"solutions", solutions},
            {"busy_note", busyNote(sceneCpuUse(s))}};
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
            {"embree_samples_per_cpu_second", c.embreeSamplesPerCpuSecond},
            {"ours_samples_per_cpu_second", c.oursSamplesPerCpuSecond},
            {"cpu_ratio", c.cpuRatio()},
            {"cpu_note", c.cpuNote},
            {"embree_cpu_seconds_per_frame", c.embreeCpuSecondsPerFrame},
            {"embree_start_cpu_seconds", c.embreeStartCpuSeconds},
            {"embree_cpu_share", c.embreeCpuUse.share()},
            {"ours_cpu_share", c.oursCpuUse.share()},
            {"busy_note", busyNote({c.embreeCpuUse, c.oursCpuUse})},
            {"image_spp", c.imageSpp},
            {"mean_radiance", {{"embree", rgb(c.embreeMean)}, {"ours", rgb(c.oursMean)}}},
            {"standard_error", rgb(c.standardError)},
            {"ours_max_pixel", c.oursMaxPixel}};
}

/// `figures` with "measured": true, or where they were not measured, why not.
json measuredJson(bool measured, const std::string& note, json figures) {
    if (!measured) return {{"measured", false}, {"note", note}};
    figures["measured"] = true;
    return figures;
}

json firstFrameJson(const FirstFrameLatency& f) {
    return measuredJson(f.measured, f.note,
                        {{"runs", f.runs},
                         {"width", f.width},
                         {"height", f.height},
                         {"first_frame_ms", f.firstFrameMs},
                         {"first_image_ms", f.firstImageMs}});
}

json memoryJson(const MemoryFigures& m) {
    return measuredJson(
        m.measured, m.note,
        {{"width", m.width}, {"height", m.height}, {"frames", m.frames}, {"peak_mib", m.peakMiB}});
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
                           {"cpu_clock", cpuClockName()},
                           {"scenes", scenes},
                           {"embree_pathtracer", peers},
                           {"scaling", scaling},
                           {"first_frame", firstFrameJson(report.firstFrame)},
                           {"memory", memoryJson(report.memory)}};
    return document.dump(2) + "\n";
}

} // namespace pathlab::bench
