#include "pathlab/render/render_stats.h"

#include "pathlab/support/cpu_clock.h"
#include "pathlab/images/image_noise.h"
#include "pathlab/support/input_error.h"
#include "pathlab/support/whole_file.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace pathlab {

double RenderStats::samplesPerSecond() const {
    return seconds > 0 ? static_cast<double>(spp) * width * height / seconds : 0.0;
}

double RenderStats::raysPerSecond() const {
    return seconds > 0 ? static_cast<double>(rays.total()) / seconds : 0.0;
}

double RenderStats::samplesPerCpuSecond() const {
    return cpuSeconds > 0 ? static_cast<double>(spp) * width * height / cpuSeconds : 0.0;
}

double RenderStats::cpuShare() const {
    return cpuSeconds > 0 && seconds > 0 && threads > 0 ? cpuSeconds / (seconds * threads) : 0.0;
}

std::string RenderStats::busyNote() const {
    // Below this share the cores were shared with other work; above, the threads' own
    // hand-offs and the last tiles of a pass account for the rest.
    constexpr double BusyShare = 0.8;
    // A render of under half a second is mostly its threads starting: its share says nothing.
    constexpr double LeastSeconds = 0.5;
    if (seconds < LeastSeconds || !(cpuShare() > 0) || cpuShare() >= BusyShare) return "";
    char text[200];
    std::snprintf(text, sizeof text,
                  "the machine was busy: the render threads had %.0f%% of their %d core(s) (%.3g "
                  "s of CPU time in %.3g s); samples per CPU-second change little with that, "
                  "samples/s and frame rates do",
                  100 * cpuShare(), threads, cpuSeconds, seconds);
    return text;
}

std::string RenderStats::cpuNote() const {
    if (!(cpuSeconds > 0)) return "";
    char text[240];
    if (cpuSeconds < 100 * cpuClockResolution()) {
        std::snprintf(text, sizeof text,
                      "the render took %.3g s of CPU time, too little for the CPU clock (a step "
                      "of %.3g s) to time precisely: render more samples to compare",
                      cpuSeconds, cpuClockResolution());
        return text;
    }
    if (cpuClock == "per-thread" && processCpuSeconds > 1.2 * cpuSeconds + 0.05) {
        std::snprintf(text, sizeof text,
                      "the process used %.3g s of CPU time besides the render threads' %.3g s "
                      "(threads of the lab's own?): samples per CPU-second count only the render "
                      "threads'",
                      processCpuSeconds - cpuSeconds, cpuSeconds);
        return text;
    }
    if (cpuClock != "per-thread") return "CPU time from the " + cpuClock;
    return "";
}

double RenderStats::efficiency() const { return renderEfficiency(noise, seconds); }

std::string RenderStats::efficiencyText() const {
    if (!(efficiency() > 0)) return "undefined (no noise)";
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", efficiency());
    return text;
}

std::string RenderStats::nonfiniteWarning() const {
    if (nonfinitePixels == 0) return "";
    std::string text = "warning: " + std::to_string(nonfinitePixels) +
                       " pixel(s) received NaN or infinite samples (left out of the image)";
    if (firstNonfinite) {
        const NonfiniteSample& f = *firstNonfinite;
        char where[256];
        std::snprintf(where, sizeof where,
                      "; the first: pixel (%d, %d), sample %llu, where lab %s (%s) returned "
                      "(%g, %g, %g) after tracing %llu ray(s) for that sample",
                      f.x, f.y, static_cast<unsigned long long>(f.sampleIndex), lab.c_str(),
                      impl.c_str(), f.radiance.r, f.radiance.g, f.radiance.b,
                      static_cast<unsigned long long>(f.raysTraced));
        text += where;
    }
    // What a student can do next: the image is made, but it is not right.
    text += ". A NaN comes from 0/0 or 0*inf in pathTrace, most often a division by a "
            "probability or a weight that can be 0: look at the divisions of the step you wrote "
            "last (the lab tests and make grade name a step only for the bugs they know)";
    return text;
}

RenderStats renderStats(const RenderedWhat& what, const AccumulationBuffer& image, int threads,
                        double seconds, const RayCounters& rays,
                        const std::optional<NonfiniteSample>& firstNonfinite, const CpuTimes& cpu) {
    RenderStats s;
    s.scene = what.scene;
    s.lab = labName(what.lab);
    s.impl = implementationName(what.implementation);
    s.spp = image.samplesPerPixel();
    s.width = image.width();
    s.height = image.height();
    s.seed = what.seed;
    s.maxDepth = what.parameters.maxDepth;
    s.continueProb = what.parameters.continueProb;
    s.threads = threads;
    s.seconds = seconds;
    s.cpuSeconds = cpu.renderThreads;
    s.processCpuSeconds = cpu.process;
    if (cpu.renderThreads > 0) s.cpuClock = cpuClockName();
    s.rays = rays;
    const AccumulationBuffer::Summary summary = image.summary();
    s.meanRadiance = summary.meanRadiance;
    s.meanVariance = summary.meanVariance;
    s.nonfinitePixels = summary.nonfinitePixels;
    s.firstNonfinite = firstNonfinite;
    s.noise = summary.noise;
    return s;
}

void setHeadlessFrameRate(RenderStats& stats) {
    const double pixels = static_cast<double>(stats.width) * stats.height;
    stats.framesPerSecond = pixels > 0 ? stats.samplesPerSecond() / pixels : 0;
    stats.framesPerSecondSource = "samples_per_second / (width x height): headless, as the "
                                  "window at this size with 1 spp per frame";
}

void writeRenderStats(const std::string& path, const RenderStats& s) {
    auto rgb = [](const Color& c) { return nlohmann::json::array({c.r, c.g, c.b}); };
    nlohmann::json json = {
        {"scene", s.scene},
        {"lab", s.lab},
        {"impl", s.impl},
        {"spp", s.spp},
        {"width", s.width},
        {"height", s.height},
        {"seed", s.seed},
        {"max_depth", s.maxDepth},
        {"continue_prob", s.continueProb},
        {"threads", s.threads},
        {"seconds", s.seconds},
        {"samples_per_second", s.samplesPerSecond()},
        {"cpu_seconds", s.cpuSeconds},
        {"process_cpu_seconds", s.processCpuSeconds},
        {"samples_per_cpu_second", s.samplesPerCpuSecond()},
        {"cpu_share", s.cpuShare()},
        {"cpu_clock", s.cpuClock},
        {"cpu_note", s.cpuNote()},
        {"busy_note", s.busyNote()},
        {"rays", {{"intersect", s.rays.intersect}, {"occluded", s.rays.occluded}}},
        {"rays_per_second", s.raysPerSecond()},
        {"mean_radiance", rgb(s.meanRadiance)},
        {"mean_variance", rgb(s.meanVariance)},
        {"nonfinite_pixels", s.nonfinitePixels},
        {"noise", s.noise},
        {"efficiency", s.efficiency()},
        {"frames_per_second", s.framesPerSecond},
        {"frames_per_second_source", s.framesPerSecondSource},
    };
    if (s.reference)
        json["reference"] = {{"file", s.reference->file},
                             {"rel_mse", s.reference->relMse},
                             {"rel_mse_epsilon", s.reference->relMseEpsilon},
                             {"relative_rmse", s.reference->relativeRmse}};
    if (s.firstNonfinite) {
        const NonfiniteSample& f = *s.firstNonfinite;
        // As text: JSON has no NaN or infinity.
        const auto component = [](float v) {
            char text[32];
            std::snprintf(text, sizeof text, "%g", v);
            return std::string(text);
        };
        json["first_nonfinite"] = {
            {"pixel", {f.x, f.y}},
            {"sample", f.sampleIndex},
            {"rays_traced", f.raysTraced},
            {"radiance",
             {component(f.radiance.r), component(f.radiance.g), component(f.radiance.b)}},
        };
    }
    writeFileAtomically(path, json.dump(2) + "\n");
}

RenderStats readRenderStats(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw InputError(path + ": cannot read the file");
    try {
        const nlohmann::json j = nlohmann::json::parse(in);
        auto rgb = [&](const char* key) {
            const nlohmann::json& c = j.at(key);
            return Color(c.at(0).get<float>(), c.at(1).get<float>(), c.at(2).get<float>());
        };
        RenderStats s;
        s.scene = j.at("scene").get<std::string>();
        s.lab = j.at("lab").get<std::string>();
        s.impl = j.at("impl").get<std::string>();
        s.spp = j.at("spp").get<int>();
        s.width = j.at("width").get<int>();
        s.height = j.at("height").get<int>();
        s.seed = j.at("seed").get<uint64_t>();
        s.maxDepth = j.at("max_depth").get<int>();
        s.continueProb = j.at("continue_prob").get<float>();
        s.threads = j.at("threads").get<int>();
        s.seconds = j.at("seconds").get<double>();
        // Stats written before CPU time was measured have none: 0, not measured.
        s.cpuSeconds = j.value("cpu_seconds", 0.0);
        s.processCpuSeconds = j.value("process_cpu_seconds", 0.0);
        s.cpuClock = j.value("cpu_clock", "");
        s.rays.intersect = j.at("rays").at("intersect").get<uint64_t>();
        s.rays.occluded = j.at("rays").at("occluded").get<uint64_t>();
        s.meanRadiance = rgb("mean_radiance");
        s.meanVariance = rgb("mean_variance");
        s.nonfinitePixels = j.at("nonfinite_pixels").get<int>();
        s.noise = j.at("noise").get<double>();
        s.framesPerSecond = j.at("frames_per_second").get<double>();
        s.framesPerSecondSource = j.at("frames_per_second_source").get<std::string>();
        if (j.contains("reference")) {
            const nlohmann::json& r = j.at("reference");
            s.reference = ReferenceFigures{
                r.at("file").get<std::string>(), r.at("rel_mse").get<double>(),
                r.at("rel_mse_epsilon").get<double>(), r.at("relative_rmse").get<double>()};
        }
        if (j.contains("first_nonfinite")) {
            const nlohmann::json& f = j.at("first_nonfinite");
            const auto component = [&](int i) {
                return std::strtof(f.at("radiance").at(i).get<std::string>().c_str(), nullptr);
            };
            s.firstNonfinite =
                NonfiniteSample{f.at("pixel").at(0).get<int>(), f.at("pixel").at(1).get<int>(),
                                f.at("sample").get<uint64_t>(), f.at("rays_traced").get<uint64_t>(),
                                Color(component(0), component(1), component(2))};
        }
        return s;
    } catch (const nlohmann::json::exception& e) {
        throw InputError(path + ": not the stats a viewer writes (" + e.what() + ")");
    }
}

} // namespace pathlab
