#pragma once
/// Renders frame after frame on a thread of its own, so the window never waits for a frame.

#include "pathlab/render/accumulation_buffer.h"
#include "pathlab/scene_io/camera.h"
#include "pathlab/render/render_identity.h"
#include "pathlab/render/render_scene.h"
#include "pathlab/render/render_stats.h"
#include "pathlab/render/lab_crash_line.h"
#include "pathlab/render/render_watchdog.h"
#include "pathlab/render/renderer.h"

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace pathlab {

/// What the window asks the renderer for: the render's identity (its size the framebuffer's),
/// and the camera, samples per frame and split view the keys change. Any change restarts
/// accumulation.
struct ViewSettings : RenderIdentity {
    CameraSettings camera;
    int sppPerFrame = 1;
    bool split = false; ///< also render the other implementation, for the split view

    bool operator==(const ViewSettings& o) const;
    bool operator!=(const ViewSettings& o) const { return !(*this == o); }
};

/// One finished frame: the accumulated image (never a partial pass) and what it cost.
struct Frame {
    ViewSettings settings;
    int number = 0;                ///< frames finished since the last restart
    std::vector<float> image;      ///< mean radiance, linear RGB, top row first
    std::vector<float> otherImage; ///< split view: the other implementation's image
    /// `image`'s per-pixel sample variance, laid out like it, for the window's noise and
    /// efficiency maps; empty unless asked for (setVarianceWanted), which costs a copy per frame.
    std::vector<float> variance;
    int otherSpp = 0;        ///< split view: the other implementation's spp
    double frameSeconds = 0; ///< wall time of the last pass
    /// The median wall time of the last 31 passes since the restart (FrameRate): the frame rate
    /// the panel and --print-frame-rate show, steady enough to write down.
    double medianFrameSeconds = 0;
    double raysPerSecond = 0; ///< of the last pass
    /// `image` as --stats describes a render: its spp, the seconds and rays of all its passes
    /// since the restart, its noise (no scene name, no frame rate: the window knows those).
    RenderStats stats;
};

class ProgressiveRenderer {
public:
    /// `onFrame` is called on the render thread after every finished frame, with its figures
    /// (its images only reach takeFrame); with `frameLimit` > 0 the renderer idles after that
    /// many frames until the next restart. With `watchdogSeconds` > 0, a pass that finishes no
    /// sample for that long ends the program (RenderWatchdog): a lab stuck in an endless loop
    /// would otherwise also keep the destructor, and so the window's close, waiting for ever.
    ProgressiveRenderer(const RenderScene& scene, int threads, const ViewSettings& settings,
                        std::function<void(const Frame&)> onFrame = {}, int frameLimit = 0,
                        double watchdogSeconds = 0);
    ~ProgressiveRenderer();

    /// Restarts accumulation with new settings (a pass in flight is abandoned).
    void update(const ViewSettings& settings);
    /// Restarts accumulation with the same settings.
    void restart();
    /// Copies the newest finished frame into `frame` if it is newer than `frame.number` after
    /// the last restart; returns whether it did.
    bool takeFrame(Frame& frame, uint64_t& generation);
    /// Why rendering stopped for good (a broken check in a lab, say), or "" while it runs.
    std::string failure();
    /// Whether frames carry their per-pixel variance (Frame::variance) from the next one on;
    /// unlike the settings, it does not restart accumulation.
    void setVarianceWanted(bool wanted) { varianceWanted_ = wanted; }
    /// Frames finished since the renderer started, over all restarts.
    int framesFinished() const { return framesFinished_.load(); }

private:
    struct Accumulation; ///< the render thread's images and totals since the last restart

    /// The render thread: pass after pass, so that the window never waits for a frame.
    void run();
    /// Idles after --frames (a done window costs no core), takes up restarts; false to stop.
    bool waitForWork(Accumulation& accumulation);
    /// One timed pass, or none if a restart abandoned it: a partial pass is never shown.
    std::optional<double> renderPass(Accumulation& accumulation, int buffer);
    /// The frame's figures without its images, for onFrame, which needs no copy of them.
    Frame frameFigures(const Accumulation& accumulation, double seconds,
                       const RayCounters& traced) const;
    /// Hands the frame to takeFrame, unless a restart made it out of date meanwhile.
    void publish(const Accumulation& accumulation, Frame frame);

    Renderer renderer_; ///< used by the render thread alone, but for its progress
    const std::function<void(const Frame&)> onFrame_;
    const int frameLimit_;
    std::mutex mutex_;
    std::condition_variable wake_;
    ViewSettings settings_;
    uint64_t generation_ = 1; ///< bumped by every restart
    bool stopping_ = false;
    std::atomic<bool> cancel_{false};
    std::atomic<bool> varianceWanted_{false};
    std::atomic<int> framesFinished_{0};
    Frame latest_;
    uint64_t latestGeneration_ = 0;
    std::string failure_;
    /// The lab and implementation of the pass under way, for the watchdog's thread to name.
    std::atomic<Lab> passLab_{Lab::Branching};
    std::atomic<Implementation> passImplementation_{Implementation::Student};
    RenderWatchdog watchdog_; ///< still watching while the destructor waits for the thread
    LabCrashLine crashLine_;  ///< names the pass's lab if its code crashes the process
    std::thread thread_;
};

} // namespace pathlab
