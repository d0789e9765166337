#include "runner/progressive_renderer.h"

#include "runner/frame_rate.h"
#include "runner/lab_tables.h"

#include <chrono>
#include <optional>
#include <utility>

namespace pathlab {

bool ViewSettings::operator==(const ViewSettings& o) const {
    const auto same = [](const Vec3& a, const Vec3& b) {
        return a.x == b.x && a.y == b.y && a.z == b.z;
    };
    return static_cast<const RenderIdentity&>(*this) == o &&
           same(camera.position, o.camera.position) && same(camera.lookAt, o.camera.lookAt) &&
           same(camera.up, o.camera.up) && camera.fovDegrees == o.camera.fovDegrees &&
           camera.leftHanded == o.camera.leftHanded && sppPerFrame == o.sppPerFrame &&
           split == o.split;
}

namespace {

/// `buffer` cleared at width × height. Its memory is reused when the size is the same, and
/// released before a new size is allocated, so a restart never holds two full-size buffers.
void resetBuffer(AccumulationBuffer& buffer, int width, int height) {
    if (buffer.width() == width && buffer.height() == height) {
        buffer.clear();
        return;
    }
    buffer = AccumulationBuffer(1, 1);
    buffer = AccumulationBuffer(width, height);
}

} // namespace

ProgressiveRenderer::ProgressiveRenderer(const RenderScene& scene, int threads,
                                         const ViewSettings& settings,
                                         std::function<void(const Frame&)> onFrame, int frameLimit,
                                         double watchdogSeconds)
    : renderer_(scene, threads), onFrame_(std::move(onFrame)), frameLimit_(frameLimit),
      settings_(settings),
      watchdog_(renderer_.progress(), watchdogSeconds,
                [this] {
                    return WatchedLab{passLab_.load(), passImplementation_.load()};
                }),
      crashLine_({settings.lab, settings.implementation}) {
    thread_ = std::thread([this] {
        // A lab's broken check (pathlab/support/check.h) or any other error ends the rendering, not
        // the program: the window reports it (failure()) and closes.
        try {
            run();
        } catch (const std::exception& error) {
            const std::lock_guard<std::mutex> lock(mutex_);
            failure_ = error.what();
        }
    });
}

ProgressiveRenderer::~ProgressiveRenderer() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
    }
    cancel_ = true;
    wake_.notify_all();
    thread_.join();
}

void ProgressiveRenderer::update(const ViewSettings& settings) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (settings == settings_) return;
    settings_ = settings;
    ++generation_;
    cancel_ = true;
    wake_.notify_all();
}

void ProgressiveRenderer::restart() {
    std::lock_guard<std::mutex> lock(mutex_);
    ++generation_;
    cancel_ = true;
    wake_.notify_all();
}

std::string ProgressiveRenderer::failure() {
    const std::lock_guard<std::mutex> lock(mutex_);
    return failure_;
}

bool ProgressiveRenderer::takeFrame(Frame& frame, uint64_t& generation) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (latestGeneration_ == 0) return false;
    if (latestGeneration_ == generation && latest_.number == frame.number) return false;
    frame = latest_;
    generation = latestGeneration_;
    return true;
}

/// Everything accumulated since the last restart; the render thread's alone.
struct ProgressiveRenderer::Accumulation {
    uint64_t generation = 0;
    ViewSettings settings;
    /// Buffer 0 is the implementation shown, buffer 1 the other one, for the split view.
    AccumulationBuffer buffers[2] = {AccumulationBuffer(1, 1), AccumulationBuffer(1, 1)};
    double seconds[2] = {0, 0};
    // The render threads' CPU time for the implementation shown. The process's is left out (0,
    // not measured): in the window it counts the drawing too, which is no lab's.
    CpuTimes cpu;
    RayCounters rays;
    std::optional<NonfiniteSample> firstNonfinite; // of the shown implementation since the restart
    FrameRate frameRate;                           // of the implementation shown (buffer 0)
    int frames = 0;

    /// Cleared buffers for new settings: a restart starts the image again.
    void restart(const ViewSettings& newSettings, uint64_t newGeneration) {
        generation = newGeneration;
        settings = newSettings;
        // The other implementation's buffer is only needed for the split view.
        resetBuffer(buffers[0], settings.width, settings.height);
        resetBuffer(buffers[1], settings.split ? settings.width : 1,
                    settings.split ? settings.height : 1);
        seconds[0] = seconds[1] = 0;
        cpu = CpuTimes();
        rays = RayCounters();
        firstNonfinite.reset();
        frameRate.clear();
        frames = 0;
    }

    /// In the split view both implementations get equal render time: the one behind goes next.
    int nextBuffer() const { return settings.split && seconds[1] < seconds[0] ? 1 : 0; }

    /// Buffer 0 holds the implementation asked for, buffer 1 the other one.
    Implementation implementationOf(int buffer) const {
        if (buffer == 0) return settings.implementation;
        return settings.implementation == Implementation::Student ? Implementation::Solution
                                                                  : Implementation::Student;
    }

    /// A finished pass into the totals; the panel's figures are of the implementation shown.
    void add(int buffer, double passSeconds, const CpuTimes& passCpu, const RayCounters& traced,
             const std::optional<NonfiniteSample>& passFirst) {
        seconds[buffer] += passSeconds;
        if (buffer == 0) {
            cpu.renderThreads += passCpu.renderThreads;
            rays += traced;
            if (passFirst && (!firstNonfinite || passFirst->before(*firstNonfinite)))
                firstNonfinite = passFirst;
            frameRate.add(passSeconds);
        }
        ++frames;
    }
};

void ProgressiveRenderer::run() {
    Accumulation accumulation;
    while (waitForWork(accumulation)) {
        const int buffer = accumulation.nextBuffer();
        const std::optional<double> seconds = renderPass(accumulation, buffer);
        if (!seconds) continue; // restarted mid-pass: the partial pass is thrown away
        const RayCounters traced = renderer_.rayCounters();
        accumulation.add(buffer, *seconds, {renderer_.cpuSeconds(), 0}, traced,
                         renderer_.firstNonfinite());
        framesFinished_.fetch_add(1);
        Frame frame = frameFigures(accumulation, *seconds, traced);
        if (onFrame_) onFrame_(frame);
        publish(accumulation, std::move(frame));
    }
}

bool ProgressiveRenderer::waitForWork(Accumulation& accumulation) {
    std::unique_lock<std::mutex> lock(mutex_);
    // After --frames frames, idle until something restarts accumulation.
    wake_.wait(lock, [&] {
        return stopping_ || accumulation.generation != generation_ || frameLimit_ == 0 ||
               accumulation.frames < frameLimit_;
    });
    if (stopping_) return false;
    if (accumulation.generation != generation_) {
        cancel_ = false;
        accumulation.restart(settings_, generation_);
    }
    return true;
}

std::optional<double> ProgressiveRenderer::renderPass(Accumulation& accumulation, int buffer) {
    const ViewSettings& settings = accumulation.settings;
    const Implementation impl = accumulation.implementationOf(buffer);
    const Camera camera(settings.camera, settings.width, settings.height);
    passLab_ = settings.lab;
    passImplementation_ = impl;
    LabCrashLine::running({settings.lab, impl});
    renderer_.resetCounts(); // this pass's rays and non-finite samples alone
    const auto start = std::chrono::steady_clock::now();
    const bool finished = renderer_.renderPass(
        accumulation.buffers[buffer], camera, findPathTrace(settings.lab, impl),
        settings.parameters, settings.seed, settings.sppPerFrame, &cancel_);
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
    if (!finished) return std::nullopt;
    return elapsed.count();
}

Frame ProgressiveRenderer::frameFigures(const Accumulation& accumulation, double seconds,
                                        const RayCounters& traced) const {
    const ViewSettings& settings = accumulation.settings;
    Frame frame;
    frame.settings = settings;
    frame.number = accumulation.frames;
    if (settings.split) frame.otherSpp = accumulation.buffers[1].samplesPerPixel();
    frame.frameSeconds = seconds;
    frame.medianFrameSeconds = accumulation.frameRate.medianSeconds();
    frame.raysPerSecond = static_cast<double>(traced.total()) / seconds;
    frame.stats = renderStats({settings, ""}, accumulation.buffers[0], renderer_.threads(),
                              accumulation.seconds[0], accumulation.rays,
                              accumulation.firstNonfinite, accumulation.cpu);
    return frame;
}

void ProgressiveRenderer::publish(const Accumulation& accumulation, Frame frame) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (accumulation.generation != generation_) return; // restarted: the frame is out of date
    // The images go straight into the published frame's memory, which the window copies from
    // under this lock: at full HD a third full-size image would be 25 MB more.
    std::vector<float> image = std::move(latest_.image);
    std::vector<float> otherImage = std::move(latest_.otherImage);
    std::vector<float> variance = std::move(latest_.variance);
    accumulation.buffers[0].meanImage(image);
    if (varianceWanted_)
        accumulation.buffers[0].varianceImage(variance);
    else
        variance.clear();
    if (accumulation.settings.split)
        accumulation.buffers[1].meanImage(otherImage);
    else
        otherImage.clear();
    latest_ = std::move(frame);
    latest_.image = std::move(image);
    latest_.otherImage = std::move(otherImage);
    latest_.variance = std::move(variance);
    latestGeneration_ = accumulation.generation;
}

} // namespace pathlab
