#include "frame_report.h"

#include "runner/frame_rate.h"
#include "runner/progressive_renderer.h"

#include "pathlab/support/input_error.h"
#include "pathlab/render/render_stats.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>

namespace pathlab::viewer {

namespace {

/// When the program started, near enough: static initialisation runs as it is loaded. The
/// first-frame latencies (--print-frame-rate, and the bench) are measured from here.
const auto programStart = std::chrono::steady_clock::now();

double millisecondsSinceStart() {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() -
                                                     programStart)
        .count();
}

/// What --stats writes for the window: a headless render's fields, for the frames shown, with
/// the panel's median frame rate.
RenderStats frameStats(const Frame& frame, const RenderOptions& options) {
    RenderStats s = frame.stats;
    s.scene = options.sceneName;
    s.framesPerSecond = perSecond(frame.medianFrameSeconds);
    s.framesPerSecondSource = "the window's median over the last " +
                              std::to_string(std::min<size_t>(frame.number, FrameRate::Window)) +
                              " frames, as its panel shows it";
    return s;
}

} // namespace

double perSecond(double seconds) { return seconds > 0 ? 1.0 / seconds : 0.0; }

void printFrameLine(const Frame& frame) {
    const ViewSettings& s = frame.settings;
    std::printf(
        "frame %d: median %.2f fps (%.1f ms) over the last %zu frames, this frame %.2f fps; "
        "%d spp, %.3g rays/s, %.3g samples per CPU-second, noise %.4f, efficiency %s; lab %s, "
        "impl %s, max-depth %d, continue-prob %.2f, size %dx%d, %s\n",
        frame.number, perSecond(frame.medianFrameSeconds), 1000.0 * frame.medianFrameSeconds,
        std::min<size_t>(frame.number, FrameRate::Window), perSecond(frame.frameSeconds),
        frame.stats.spp, frame.raysPerSecond, frame.stats.samplesPerCpuSecond(), frame.stats.noise,
        frame.stats.efficiencyText().c_str(), std::string(labName(s.lab)).c_str(),
        std::string(implementationName(s.implementation)).c_str(), s.parameters.maxDepth,
        s.parameters.continueProb, s.width, s.height, s.split ? "split" : "single");
    std::fflush(stdout);
}

void printMillisecondsSinceStart(const char* event) {
    std::printf("%s: %.1f ms after start\n", event, millisecondsSinceStart());
    std::fflush(stdout);
}

bool writeWindowStats(const RenderOptions& options, const Frame& frame) {
    if (frame.number == 0) {
        std::fprintf(stderr, "viewer: --stats %s: no frame was finished, nothing written\n",
                     options.statsFile.c_str());
        return false;
    }
    try {
        writeRenderStats(options.statsFile, frameStats(frame, options));
    } catch (const InputError& error) {
        std::fprintf(stderr, "viewer: %s\n", error.what());
        return false;
    }
    return true;
}

} // namespace pathlab::viewer
