// The progressive window: GLFW for the window and input, OpenGL 2 to show the image, Dear ImGui
// for the panel. Rendering runs in ProgressiveRenderer's thread; this file only shows and steers.
#include "viewer_window.h"

#include "camera_controller.h"

#include "runner/frame_rate.h"
#include "runner/lab_tables.h"
#include "runner/progressive_renderer.h"

#include "pathlab/false_colour.h"
#include "pathlab/image_io.h"
#include "pathlab/input_error.h"
#include "pathlab/render_scene.h"
#include "pathlab/render_stats.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl2.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <string>
#include <utility>

namespace pathlab::viewer {

namespace {

enum class ViewMode { Image, Difference, Split };

const char* viewModeName(ViewMode mode) {
    switch (mode) {
    case ViewMode::Image: return "image";
    case ViewMode::Difference: return "difference to --reference";
    case ViewMode::Split: return "split: student left, solution right, equal time";
    }
    return "?";
}

std::string glfwProblem;

double perSecond(double seconds) { return seconds > 0 ? 1.0 / seconds : 0.0; }

/// When the program started, near enough: static initialisation runs as it is loaded. The
/// first-frame latencies (--print-frame-rate, and the bench) are measured from here.
const auto programStart = std::chrono::steady_clock::now();

double millisecondsSinceStart() {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() -
                                                     programStart)
        .count();
}

/// --print-frame-rate: one line per finished frame, with the figures the panel shows, labelled.
/// "; the first at pixel (x, y), sample n", or nothing.
std::string firstNonfiniteText(const RenderStats& stats) {
    if (!stats.firstNonfinite) return "";
    const NonfiniteSample& f = *stats.firstNonfinite;
    return "; the first at pixel (" + std::to_string(f.x) + ", " + std::to_string(f.y) +
           "), sample " + std::to_string(f.sampleIndex);
}

void printFrameLine(const Frame& frame) {
    const ViewSettings& s = frame.settings;
    std::printf(
        "frame %d: median %.2f fps (%.1f ms) over the last %zu frames, this frame %.2f fps; "
        "%d spp, %.3g rays/s, noise %.4f, efficiency %s; lab %s, impl %s, max-depth %d, "
        "continue-prob %.2f, size %dx%d, %s\n",
        frame.number, perSecond(frame.medianFrameSeconds), 1000.0 * frame.medianFrameSeconds,
        std::min<size_t>(frame.number, FrameRate::Window), perSecond(frame.frameSeconds),
        frame.stats.spp, frame.raysPerSecond, frame.stats.noise,
        frame.stats.efficiencyText().c_str(), std::string(labName(s.lab)).c_str(),
        std::string(implementationName(s.implementation)).c_str(), s.parameters.maxDepth,
        s.parameters.continueProb, s.width, s.height, s.split ? "split" : "single");
    std::fflush(stdout);
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

/// The keys, the labs' from the list of labs.
std::string helpText() {
    return "h        this help\n"
           "f        fullscreen on/off\n"
           "drag     orbit the camera\n"
           "WASD     move (arrow keys too)\n"
           "1-" +
           std::to_string(AllLabs.size()) + "      lab: " + labNames(", ") +
           "\n"
           "Tab      your code <-> reference solution\n"
           "+ / -    continueProb up / down (lab 4)\n"
           "[ / ]    maxDepth down / up (labs 1-3)\n"
           "v        view: image, difference, split\n"
           "r        restart accumulation\n"
           "Space    screenshot (.exr linear + .png)\n"
           "c        print the camera as .ecs options\n"
           "Esc, q   quit";
}

class ViewerWindow {
public:
    ViewerWindow(const RenderOptions& options, const WindowOptions& windowOptions,
                 GLFWwindow* window, const RenderScene& scene)
        : options_(options), windowOptions_(windowOptions), window_(window) {
        settings_.lab = options.lab;
        settings_.implementation = options.implementation;
        settings_.parameters = options.parameters;
        settings_.camera = scene.scene().camera.value_or(scene.scene().framingCamera());
        glfwGetFramebufferSize(window, &settings_.width, &settings_.height);
        settings_.sppPerFrame = windowOptions.sppPerFrame;
        settings_.seed = options.seed;
        if (!windowOptions.referenceImage.empty())
            reference_ = readImage(windowOptions.referenceImage);
        std::function<void(const Frame&)> print;
        if (windowOptions.printFrameRate) print = printFrameLine;
        renderer_ =
            std::make_unique<ProgressiveRenderer>(scene, options.threads, settings_, print,
                                                  windowOptions.frames, options.watchdogSeconds);
        glGenTextures(1, &texture_);
    }

    ~ViewerWindow() { glDeleteTextures(1, &texture_); }

    /// Runs until the window closes; returns the exit status.
    int run() {
        while (!glfwWindowShouldClose(window_)) {
            glfwWaitEventsTimeout(1.0 / 60.0);
            renderer_->update(settings_);
            const bool fresh = renderer_->takeFrame(frame_, generation_);
            if (fresh) onNewFrame();
            // Drawing only what changed leaves the cores to the render thread: an idle redraw at
            // 60 Hz costs a software-rendered display (Xvfb, a remote desktop) a share of them.
            if (fresh || std::exchange(inputSeen_, false) || finishing_) draw();
            if (done_) break;
            if (const std::string failure = renderer_->failure(); !failure.empty()) {
                std::fprintf(stderr, "viewer: error: %s\n", failure.c_str());
                return 1;
            }
        }
        if (!options_.statsFile.empty()) writeStats();
        return status_;
    }

    void onKey(int key, int action, int mods) {
        inputSeen_ = true;
        if (action == GLFW_RELEASE) return;
        const bool repeat = action == GLFW_REPEAT;
        const float step = 0.02f * length(settings_.camera.lookAt - settings_.camera.position);
        switch (key) {
        case GLFW_KEY_W:
        case GLFW_KEY_UP: settings_.camera = move(settings_.camera, step, 0); return;
        case GLFW_KEY_S:
        case GLFW_KEY_DOWN: settings_.camera = move(settings_.camera, -step, 0); return;
        case GLFW_KEY_A:
        case GLFW_KEY_LEFT: settings_.camera = move(settings_.camera, 0, -step); return;
        case GLFW_KEY_D:
        case GLFW_KEY_RIGHT: settings_.camera = move(settings_.camera, 0, step); return;
        default: break;
        }
        if (repeat) return;
        // The number keys choose the labs, in the order of pathlab/lab_list.h.
        if (key >= GLFW_KEY_1 && key < GLFW_KEY_1 + static_cast<int>(AllLabs.size())) {
            settings_.lab = AllLabs[static_cast<size_t>(key - GLFW_KEY_1)];
            return;
        }
        switch (key) {
        case GLFW_KEY_ESCAPE:
        case GLFW_KEY_Q: glfwSetWindowShouldClose(window_, GLFW_TRUE); break;
        case GLFW_KEY_H: showHelp_ = !showHelp_; break;
        case GLFW_KEY_F: toggleFullscreen(); break;
        case GLFW_KEY_TAB:
            if (!solution::available()) {
                std::printf("Tab: the reference solutions are not part of this build\n");
                std::fflush(stdout);
                break;
            }
            settings_.implementation = settings_.implementation == Implementation::Student
                                           ? Implementation::Solution
                                           : Implementation::Student;
            break;
        case GLFW_KEY_EQUAL:
        case GLFW_KEY_KP_ADD:
            settings_.parameters.continueProb =
                std::min(0.95f, settings_.parameters.continueProb + 0.05f);
            break;
        case GLFW_KEY_MINUS:
        case GLFW_KEY_KP_SUBTRACT:
            settings_.parameters.continueProb =
                std::max(0.05f, settings_.parameters.continueProb - 0.05f);
            break;
        case GLFW_KEY_LEFT_BRACKET:
            settings_.parameters.maxDepth = std::max(0, settings_.parameters.maxDepth - 1);
            break;
        case GLFW_KEY_RIGHT_BRACKET:
            settings_.parameters.maxDepth = std::min(64, settings_.parameters.maxDepth + 1);
            break;
        case GLFW_KEY_R: renderer_->restart(); break;
        case GLFW_KEY_V: cycleViewMode(); break;
        case GLFW_KEY_SPACE: screenshot(""); break;
        case GLFW_KEY_C:
            std::printf("%s\n", cameraAsOptions(settings_.camera).c_str());
            std::fflush(stdout);
            break;
        default: break;
        }
        (void)mods;
    }

    /// The window must be drawn again (uncovered, or input the panel may show).
    void onRefresh() { inputSeen_ = true; }

    void onFramebufferSize(int width, int height) {
        inputSeen_ = true;
        if (width > 0 && height > 0) settings_.width = width, settings_.height = height;
    }

    void onMouseButton(int button, int action) {
        inputSeen_ = true;
        if (button != GLFW_MOUSE_BUTTON_LEFT) return;
        dragging_ = action == GLFW_PRESS && !ImGui::GetIO().WantCaptureMouse;
        glfwGetCursorPos(window_, &lastX_, &lastY_);
    }

    void onCursor(double x, double y) {
        inputSeen_ = true;
        if (!dragging_) return;
        settings_.camera = orbit(settings_.camera, static_cast<float>(x - lastX_) * 0.005f,
                                 static_cast<float>(y - lastY_) * 0.005f);
        lastX_ = x, lastY_ = y;
    }

private:
    void cycleViewMode() {
        // The split view needs the reference solutions, which the student release lacks.
        if (mode_ == ViewMode::Image)
            mode_ = reference_.width > 0    ? ViewMode::Difference
                    : solution::available() ? ViewMode::Split
                                            : ViewMode::Image;
        else if (mode_ == ViewMode::Difference && solution::available())
            mode_ = ViewMode::Split;
        else
            mode_ = ViewMode::Image;
        settings_.split = mode_ == ViewMode::Split;
        if (settings_.split) settings_.implementation = Implementation::Student;
    }

    void toggleFullscreen() {
        if (glfwGetWindowMonitor(window_)) {
            glfwSetWindowMonitor(window_, nullptr, windowedX_, windowedY_, windowedWidth_,
                                 windowedHeight_, 0);
            return;
        }
        GLFWmonitor* monitor = glfwGetPrimaryMonitor();
        if (!monitor) return;
        const GLFWvidmode* video = glfwGetVideoMode(monitor);
        glfwGetWindowPos(window_, &windowedX_, &windowedY_);
        glfwGetWindowSize(window_, &windowedWidth_, &windowedHeight_);
        glfwSetWindowMonitor(window_, monitor, 0, 0, video->width, video->height,
                             video->refreshRate);
    }

    void onNewFrame() {
        const ViewSettings& s = frame_.settings;
        if (windowOptions_.printFrameRate && !firstFrameSeen_) {
            std::printf("first frame: %.1f ms after start\n", millisecondsSinceStart());
            std::fflush(stdout);
        }
        firstFrameSeen_ = true;
        uploadImage();
        if (windowOptions_.frames > 0 && frame_.number >= windowOptions_.frames && s == settings_) {
            if (!windowOptions_.screenshot.empty()) screenshot(windowOptions_.screenshot);
            finishing_ = true; // the next draw captures the window if asked, then the loop ends
        }
    }

    void uploadImage() {
        const int w = frame_.settings.width, h = frame_.settings.height;
        if (mode_ == ViewMode::Difference && reference_.width == w && reference_.height == h) {
            medianDifference_ = relativeDifferenceImage(frame_.image, reference_.rgb, 0.5f, rgba_);
        } else if (mode_ == ViewMode::Split && !frame_.otherImage.empty()) {
            std::vector<float> composed = frame_.image;
            for (int y = 0; y < h; ++y)
                for (int x = w / 2; x < w; ++x)
                    for (int c = 0; c < 3; ++c)
                        composed[3 * (y * w + x) + c] = frame_.otherImage[3 * (y * w + x) + c];
            toDisplay(composed, rgba_);
        } else {
            toDisplay(frame_.image, rgba_);
        }
        glBindTexture(GL_TEXTURE_2D, texture_);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba_.data());
        hasImage_ = true;
    }

    void draw() {
        int width = 0, height = 0;
        glfwGetFramebufferSize(window_, &width, &height);
        glViewport(0, 0, width, height);
        glClearColor(0, 0, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        if (hasImage_) {
            glMatrixMode(GL_PROJECTION);
            glLoadIdentity();
            glMatrixMode(GL_MODELVIEW);
            glLoadIdentity();
            glEnable(GL_TEXTURE_2D);
            glBindTexture(GL_TEXTURE_2D, texture_);
            glBegin(GL_QUADS); // the image's first row is its top: flip t
            glTexCoord2f(0, 1), glVertex2f(-1, -1);
            glTexCoord2f(1, 1), glVertex2f(1, -1);
            glTexCoord2f(1, 0), glVertex2f(1, 1);
            glTexCoord2f(0, 0), glVertex2f(-1, 1);
            glEnd();
            glDisable(GL_TEXTURE_2D);
        }
        drawPanel();
        if (finishing_) {
            if (!windowOptions_.windowCapture.empty()) captureWindow(width, height);
            done_ = true;
        }
        glfwSwapBuffers(window_);
        if (windowOptions_.printFrameRate && hasImage_ && !firstImageShown_) {
            glFinish(); // the image is on screen, not only queued
            std::printf("first image on screen: %.1f ms after start\n", millisecondsSinceStart());
            std::fflush(stdout);
        }
        firstImageShown_ = firstImageShown_ || hasImage_;
    }

    void captureWindow(int width, int height) {
        std::vector<unsigned char> bottomUp(3 * static_cast<size_t>(width) * height),
            rgb(bottomUp.size());
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadBuffer(GL_BACK);
        glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, bottomUp.data());
        const size_t row = 3 * static_cast<size_t>(width);
        for (int y = 0; y < height; ++y) // OpenGL's rows start at the bottom
            std::copy_n(&bottomUp[(height - 1 - y) * row], row, &rgb[y * row]);
        try {
            writeDisplayImage(windowOptions_.windowCapture, width, height, rgb);
            std::printf("window capture %s\n", windowOptions_.windowCapture.c_str());
        } catch (const InputError& error) {
            std::fprintf(stderr, "viewer: %s\n", error.what());
            status_ = 2;
        }
    }

    void drawPanel() {
        ImGui_ImplOpenGL2_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
        ImGui::SetNextWindowBgAlpha(0.6f);
        ImGui::Begin("PathLab", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
        const ViewSettings& s = frame_.settings;
        ImGui::Text("%.2f fps  %.1f ms/frame (median)", perSecond(frame_.medianFrameSeconds),
                    1000.0 * frame_.medianFrameSeconds);
        ImGui::Text("%d spp   %.3g rays/s", frame_.stats.spp, frame_.raysPerSecond);
        ImGui::Text("lab %s (%s)", std::string(labName(settings_.lab)).c_str(),
                    std::string(implementationName(settings_.implementation)).c_str());
        ImGui::Text("maxDepth %d   continueProb %.2f", settings_.parameters.maxDepth,
                    settings_.parameters.continueProb);
        ImGui::Text("noise %.4f (relative std. error)  efficiency %s", frame_.stats.noise,
                    frame_.stats.efficiencyText().c_str());
        ImGui::Text("%dx%d  view: %s", s.width, s.height, viewModeName(mode_));
        if (mode_ == ViewMode::Split)
            ImGui::Text("student %d spp | solution %d spp", frame_.stats.spp, frame_.otherSpp);
        if (mode_ == ViewMode::Difference)
            ImGui::Text("|image - ref| / ref: black 0, blue .125, green .25, yellow .375, red .5+;"
                        " median %.3f",
                        medianDifference_);
        if (frame_.stats.nonfinitePixels > 0)
            ImGui::TextColored(ImVec4(1, 0.3f, 0.3f, 1), "%d pixels got NaN/inf samples%s",
                               frame_.stats.nonfinitePixels,
                               firstNonfiniteText(frame_.stats).c_str());
        ImGui::Text("h: help");
        ImGui::End();
        if (showHelp_) {
            ImGui::SetNextWindowPos(ImVec2(8, 200), ImGuiCond_FirstUseEver);
            ImGui::Begin("Keys", &showHelp_, ImGuiWindowFlags_AlwaysAutoResize);
            ImGui::TextUnformatted(helpText().c_str());
            ImGui::End();
        }
        ImGui::Render();
        ImGui_ImplOpenGL2_RenderDrawData(ImGui::GetDrawData());
    }

    void writeStats() {
        if (frame_.number == 0) {
            std::fprintf(stderr, "viewer: --stats %s: no frame was finished, nothing written\n",
                         options_.statsFile.c_str());
            status_ = 2;
            return;
        }
        try {
            writeRenderStats(options_.statsFile, frameStats(frame_, options_));
        } catch (const InputError& error) {
            std::fprintf(stderr, "viewer: %s\n", error.what());
            status_ = 2;
        }
    }

    void screenshot(const std::string& requested) {
        if (frame_.image.empty()) return;
        const ViewSettings& s = frame_.settings;
        const int w = s.width, h = s.height;
        try {
            if (!requested.empty()) {
                writeImage(requested, w, h, frame_.image);
                std::printf("screenshot %s (%d spp)\n", requested.c_str(), frame_.stats.spp);
            } else {
                const std::string base = "pathlab-" + std::string(labName(s.lab)) + "-" +
                                         std::string(implementationName(s.implementation)) + "-" +
                                         std::to_string(frame_.stats.spp) + "spp";
                writeImage(base + ".exr", w, h, frame_.image);
                writeImage(base + ".png", w, h, frame_.image);
                std::printf("screenshot %s.exr and %s.png\n", base.c_str(), base.c_str());
            }
        } catch (const InputError& error) {
            std::fprintf(stderr, "viewer: %s\n", error.what());
            status_ = 2;
        }
        std::fflush(stdout);
    }

    const RenderOptions& options_;
    const WindowOptions& windowOptions_;
    GLFWwindow* window_;
    ViewSettings settings_;
    std::unique_ptr<ProgressiveRenderer> renderer_;
    Image reference_;
    Frame frame_;
    uint64_t generation_ = 0;
    std::vector<unsigned char> rgba_;
    unsigned texture_ = 0;
    bool inputSeen_ = true; // the first loop draws the panel before any frame
    bool hasImage_ = false, showHelp_ = false, finishing_ = false, done_ = false, dragging_ = false;
    bool firstFrameSeen_ = false, firstImageShown_ = false; ///< for --print-frame-rate
    ViewMode mode_ = ViewMode::Image;
    float medianDifference_ = 0;
    double lastX_ = 0, lastY_ = 0;
    int windowedX_ = 0, windowedY_ = 0, windowedWidth_ = 0, windowedHeight_ = 0;
    int status_ = 0;
};

ViewerWindow* windowOf(GLFWwindow* w) {
    return static_cast<ViewerWindow*>(glfwGetWindowUserPointer(w));
}

/// glfwInit/glfwTerminate and ImGui's context, released whatever happens.
struct GlfwSession {
    GLFWwindow* window = nullptr;
    bool imgui = false;
    ~GlfwSession() {
        if (imgui) {
            ImGui_ImplOpenGL2_Shutdown();
            ImGui_ImplGlfw_Shutdown();
            ImGui::DestroyContext();
        }
        if (window) glfwDestroyWindow(window);
        glfwTerminate();
    }
};

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
#if defined(__linux__) || defined(__FreeBSD__)
    // X11 or Wayland: with neither variable set there is no screen to open a window on, and
    // saying so is clearer than GLFW's error. (macOS and Windows always have their one screen;
    // there glfwInit says when it cannot be used, e.g. over ssh.)
    const char* display = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    if ((!display || !*display) && (!wayland || !*wayland)) return noDisplay("DISPLAY is not set");
#endif

    // The scene first: a broken scene is reported as such, before any window appears.
    const pathlab::RenderScene scene(pathlab::loadScene(options));

    glfwSetErrorCallback([](int, const char* message) { glfwProblem = message; });
    GlfwSession session;
    if (!glfwInit()) return noDisplay(glfwProblem);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 2);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 1);
    // The window is sized in screen coordinates; on HiDPI screens the framebuffer, which is
    // what gets rendered, is larger.
    session.window = glfwCreateWindow(options.width, options.height, "PathLab", nullptr, nullptr);
    if (!session.window) return noDisplay(glfwProblem);
    glfwMakeContextCurrent(session.window);
    glfwSwapInterval(0);

    ViewerWindow viewer(options, windowOptions, session.window, scene);
    glfwSetWindowUserPointer(session.window, &viewer);
    glfwSetKeyCallback(session.window, [](GLFWwindow* w, int key, int, int action, int mods) {
        windowOf(w)->onKey(key, action, mods);
    });
    glfwSetFramebufferSizeCallback(session.window, [](GLFWwindow* w, int width, int height) {
        windowOf(w)->onFramebufferSize(width, height);
    });
    glfwSetMouseButtonCallback(session.window, [](GLFWwindow* w, int button, int action, int) {
        windowOf(w)->onMouseButton(button, action);
    });
    glfwSetCursorPosCallback(
        session.window, [](GLFWwindow* w, double x, double y) { windowOf(w)->onCursor(x, y); });
    glfwSetWindowRefreshCallback(session.window, [](GLFWwindow* w) { windowOf(w)->onRefresh(); });
    // ImGui chains to the callbacks above (install_callbacks = true).
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr; // no imgui.ini littering the build folder
    ImGui_ImplGlfw_InitForOpenGL(session.window, true);
    ImGui_ImplOpenGL2_Init();
    session.imgui = true;
    return viewer.run();
}
