// The progressive window's frame loop: it ties the input, the panel and the texture to the
// renderer. Rendering runs in ProgressiveRenderer's thread; this file only shows and steers.
#include "viewer_window.h"

#include "convergence_plot.h"
#include "frame_report.h"
#include "frame_texture.h"
#include "glfw_session.h"
#include "path_inspector_panel.h"
#include "screenshots.h"
#include "view_mode.h"
#include "viewer_panel.h"
#include "warp_test_panel.h"
#include "window_input.h"

#include "runner/lab_tables.h"
#include "runner/progressive_renderer.h"

#include "pathlab/render/scene_from_options.h"
#include "pathlab/images/image_io.h"
#include "pathlab/render/render_scene.h"

#include <GLFW/glfw3.h>

#include <cstdio>
#include <functional>
#include <string>

namespace pathlab::viewer {

namespace {

/// What the window asks for first: the options' lab, the scene's camera (or one that frames
/// it), at the size the window's framebuffer got.
ViewSettings initialSettings(const RenderOptions& options, const WindowOptions& windowOptions,
                             GLFWwindow* window, const RenderScene& scene) {
    ViewSettings settings;
    static_cast<RenderIdentity&>(settings) = options; // its size is the framebuffer's, below
    settings.camera = scene.scene().camera.value_or(scene.scene().framingCamera());
    glfwGetFramebufferSize(window, &settings.width, &settings.height);
    settings.sppPerFrame = windowOptions.sppPerFrame;
    return settings;
}

/// The difference view's reference, read before the first frame so that a bad file stops the
/// window at once; none without --reference.
Image referenceImage(const WindowOptions& windowOptions) {
    if (windowOptions.referenceImage.empty()) return Image();
    return readImage(windowOptions.referenceImage);
}

/// --print-frame-rate's line for every frame, printed on the render thread as it finishes, so
/// that no frame goes unreported while the window is busy.
std::function<void(const Frame&)> frameLines(const WindowOptions& windowOptions) {
    if (!windowOptions.printFrameRate) return {};
    return printFrameLine;
}

class ViewerWindow {
public:
    ViewerWindow(const RenderOptions& options, const WindowOptions& windowOptions,
                 GLFWwindow* window, const RenderScene& scene)
        : options_(options), windowOptions_(windowOptions), window_(window),
          settings_(initialSettings(options, windowOptions, window, scene)),
          reference_(referenceImage(windowOptions)),
          convergence_(findConvergenceReference(options, windowOptions.referenceImage, reference_,
                                                settings_.width, settings_.height),
                       settings_.camera),
          renderer_(scene, options.threads, settings_, frameLines(windowOptions),
                    windowOptions.frames, options.watchdogSeconds),
          input_(window, settings_), inspector_(options, scene), warp_(options.watchdogSeconds) {
        panel_.alsoDraw([this] {
            inspector_.draw(settings_);
            warp_.draw();
        });
        if (windowOptions.warpPanel) warp_.run(settings_.lab, settings_.implementation);
        if (options.inspect) inspector_.inspect(settings_, options.inspectX, options.inspectY);
        if (windowOptions.view) {
            mode_ = *windowOptions.view;
            showMode();
            renderer_.update(settings_);
        }
    }

    /// Runs until the window closes; returns the exit status.
    int run() {
        while (!glfwWindowShouldClose(window_)) {
            glfwWaitEventsTimeout(1.0 / 60.0);
            renderer_.update(settings_);
            if (const auto pixel = input_.takeClickedPixel())
                inspector_.inspect(settings_, pixel->first, pixel->second);
            const bool inspected = inspector_.poll();
            const bool fresh = renderer_.takeFrame(frame_, generation_);
            if (fresh) onNewFrame();
            finishWhenDone();
            // Drawing only what changed leaves the cores to the render thread: an idle redraw at
            // 60 Hz costs a software-rendered display (Xvfb, a remote desktop) a share of them.
            if (fresh || inspected || input_.takeSeen() || finishing_) draw();
            if (done_) break;
            if (const std::string failure = renderer_.failure(); !failure.empty()) {
                std::fprintf(stderr, "viewer: error: %s\n", failure.c_str());
                return 1;
            }
        }
        if (!options_.statsFile.empty() && !writeWindowStats(options_, frame_)) status_ = 2;
        return status_;
    }

    WindowInput& input() { return input_; }

    void onKey(int key, int action) {
        switch (input_.onKey(key, action)) {
        case KeyCommand::None: break;
        case KeyCommand::Restart: renderer_.restart(); break;
        case KeyCommand::NextViewMode: nextMode(); break;
        case KeyCommand::Screenshot: screenshot(""); break;
        case KeyCommand::ToggleHelp: panel_.toggleHelp(); break;
        case KeyCommand::WarpTest: warp_.run(settings_.lab, settings_.implementation); break;
        }
    }

private:
    /// The v key: the next mode this run can show.
    void nextMode() {
        mode_ = nextViewMode(mode_, reference_.width > 0, solution::available());
        showMode();
    }

    /// The split view renders both implementations, the student's as the one shown; the maps
    /// need each frame's variance.
    void showMode() {
        settings_.split = mode_ == ViewMode::Split;
        if (settings_.split) settings_.implementation = Implementation::Student;
        renderer_.setVarianceWanted(isMapMode(mode_));
    }

    /// The frame on screen, and with --frames, the end of the run once the last one is in.
    void onNewFrame() {
        if (windowOptions_.printFrameRate && !firstFrameSeen_)
            printMillisecondsSinceStart("first frame");
        firstFrameSeen_ = true;
        texture_.upload(frame_, mode_, reference_);
        convergence_.onFrame(frame_);
        if (windowOptions_.frames > 0 && frame_.number >= windowOptions_.frames &&
            frame_.settings == settings_)
            lastFrameIn_ = true;
    }

    /// With --frames, the end of the run once the last frame is in and a pixel inspected from
    /// the start (--inspect-window) has its replay, so that the window captured shows its paths.
    void finishWhenDone() {
        if (!lastFrameIn_ || finishing_ || inspector_.busy()) return;
        // ImGui lays out a window that fits its contents in its first frame and shows it from the
        // second: a capture needs two drawn before it (the frames may all be in before the first
        // draw, when the window's start took a while, a warp test's say).
        while (draws_ < 2) draw();
        if (!windowOptions_.screenshot.empty()) screenshot(windowOptions_.screenshot);
        finishing_ = true; // the next draw captures the window if asked, then the loop ends
    }

    void draw() {
        ++draws_;
        int width = 0, height = 0;
        glfwGetFramebufferSize(window_, &width, &height);
        glViewport(0, 0, width, height);
        glClearColor(0, 0, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        texture_.draw();
        panel_.draw(frame_, settings_, mode_, texture_.medianDifference(), texture_.mapScale(),
                    [this] { convergence_.draw(); });
        if (finishing_) {
            if (!windowOptions_.windowCapture.empty() &&
                !captureWindow(windowOptions_.windowCapture, width, height))
                status_ = 2;
            done_ = true;
        }
        glfwSwapBuffers(window_);
        if (windowOptions_.printFrameRate && texture_.hasImage() && !firstImageShown_) {
            glFinish(); // the image is on screen, not only queued
            printMillisecondsSinceStart("first image on screen");
        }
        firstImageShown_ = firstImageShown_ || texture_.hasImage();
    }

    void screenshot(const std::string& requested) {
        if (!saveScreenshot(frame_, requested)) status_ = 2;
    }

    const RenderOptions& options_;
    const WindowOptions& windowOptions_;
    GLFWwindow* window_;
    ViewSettings settings_; ///< what the renderer is asked for; input changes it
    Image reference_;
    ConvergencePlot convergence_; ///< against reference_, or the cached one of this size
    ProgressiveRenderer renderer_;
    FrameTexture texture_;
    WindowInput input_;
    PathInspectorPanel inspector_; ///< replays on a worker thread of its own (inspection_job.h)
    WarpTestPanel warp_;           ///< the t key's warp test, run on this thread
    int draws_ = 0;                ///< draw() calls so far
    ViewerPanel panel_;
    Frame frame_;
    uint64_t generation_ = 0;
    ViewMode mode_ = ViewMode::Image;
    bool lastFrameIn_ = false, finishing_ = false, done_ = false;
    bool firstFrameSeen_ = false, firstImageShown_ = false; ///< for --print-frame-rate
    int status_ = 0;
};

ViewerWindow* windowOf(GLFWwindow* w) {
    return static_cast<ViewerWindow*>(glfwGetWindowUserPointer(w));
}

/// GLFW's callbacks to the viewer, which the window's user pointer names.
void connectCallbacks(GLFWwindow* window, ViewerWindow& viewer) {
    glfwSetWindowUserPointer(window, &viewer);
    glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int, int action, int) {
        windowOf(w)->onKey(key, action);
    });
    glfwSetFramebufferSizeCallback(window, [](GLFWwindow* w, int width, int height) {
        windowOf(w)->input().onFramebufferSize(width, height);
    });
    glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int button, int action, int mods) {
        windowOf(w)->input().onMouseButton(button, action, mods);
    });
    glfwSetCursorPosCallback(
        window, [](GLFWwindow* w, double x, double y) { windowOf(w)->input().onCursor(x, y); });
    glfwSetWindowRefreshCallback(window, [](GLFWwindow* w) { windowOf(w)->input().onRefresh(); });
}

int noDisplay(const std::string& why) {
    std::fprintf(stderr,
                 "viewer: no display (%s): the window cannot open; render headless "
                 "instead with -o FILE.png --spp N (see viewer --help)\n",
                 why.c_str());
    return 2;
}

} // namespace

} // namespace pathlab::viewer

int runViewerWindow(const pathlab::RenderOptions& options,
                    const pathlab::viewer::WindowOptions& windowOptions) {
    using namespace pathlab::viewer;
    if (const std::string why = missingDisplay(); !why.empty()) return noDisplay(why);

    // The scene first: a broken scene is reported as such, before any window appears.
    const pathlab::RenderScene scene(pathlab::loadScene(options));

    GlfwSession session;
    if (!session.open(options.width, options.height)) return noDisplay(GlfwSession::problem());
    ViewerWindow viewer(options, windowOptions, session.window(), scene);
    connectCallbacks(session.window(), viewer);
    session.startImGui(); // ImGui chains to the callbacks above (install_callbacks = true)
    return viewer.run();
}
