#include "memory_probe.h"

#include "runner/progressive_renderer.h"

#include "process/child_process.h"

#include "pathlab/images/false_colour.h"
#include "pathlab/render/render_options.h"
#include "pathlab/render/scene_from_options.h"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <thread>

namespace pathlab::bench {

namespace {

/// How the probe reports its peak, in KiB, on standard output.
constexpr const char* PeakKey = "peak resident KiB: ";

/// This process's peak resident memory since it started its program (VmHWM).
long peakResidentKiB() {
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);)
        if (line.rfind("VmHWM:", 0) == 0) return std::stol(line.substr(6));
    return 0;
}

} // namespace

MemoryFigures measurePeakMemory(const std::string& self, const BenchScene& scene,
                                const BenchOptions& options) {
    MemoryFigures m;
    m.width = options.memoryWidth;
    m.height = options.memoryHeight;
    m.frames = options.memoryFrames;
    if (m.frames == 0) {
        m.note = "skipped (--memory-frames 0)";
        return m;
    }
    std::fprintf(stderr, "bench: peak memory ...\n");
    std::vector<std::string> argv = {self,
                                     "--memory-probe",
                                     "--memory-size",
                                     std::to_string(m.width),
                                     std::to_string(m.height),
                                     "--memory-frames",
                                     std::to_string(m.frames),
                                     "--scene",
                                     scene.file};
    if (options.threads > 0) {
        argv.push_back("--threads");
        argv.push_back(std::to_string(options.threads));
    }
    const ChildRun child = runChild(argv);
    // The probe reports its own high-water mark: getrusage's figure for a child also counts
    // what the parent held when the child was spawned (Linux records the pre-exec memory).
    const size_t at = child.output.find(PeakKey);
    if (child.exitCode != 0 || at == std::string::npos) {
        m.note = "the probe failed: " + child.output.substr(0, 400);
        return m;
    }
    m.peakMiB = std::stod(child.output.substr(at + std::strlen(PeakKey))) / 1024.0;
    m.measured = true;
    return m;
}

int runMemoryProbe(const BenchScene& benchScene, const BenchOptions& options) {
    const RenderOptions renderOptions =
        renderOptionsFor(benchScene, options.memoryWidth, options.memoryHeight);
    const RenderScene scene(loadScene(renderOptions));
    ViewSettings settings;
    settings.lab = Lab::Importance;
    settings.implementation = Implementation::Solution;
    settings.parameters = options.parameters;
    settings.camera = scene.scene().camera.value_or(scene.scene().framingCamera());
    settings.width = options.memoryWidth;
    settings.height = options.memoryHeight;

    ProgressiveRenderer renderer(scene, options.threads, settings, {}, options.memoryFrames);
    // The window's side: take each new frame and turn it into display pixels.
    Frame frame;
    uint64_t generation = 0;
    std::vector<unsigned char> rgba;
    while (frame.number < options.memoryFrames) {
        if (renderer.takeFrame(frame, generation))
            toDisplay(frame.image, rgba);
        else
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    std::printf("%s%ld\n", PeakKey, peakResidentKiB());
    return 0;
}

} // namespace pathlab::bench
