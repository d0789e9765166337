#include "viewer_panel.h"

#include "frame_report.h"
#include "window_input.h"

#include "runner/progressive_renderer.h"

#include "pathlab/images/scale_bar.h"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl2.h>

#include <string>

namespace pathlab::viewer {

namespace {

/// "; the first at pixel (x, y), sample n", or nothing.
std::string firstNonfiniteText(const RenderStats& stats) {
    if (!stats.firstNonfinite) return "";
    const NonfiniteSample& f = *stats.firstNonfinite;
    return "; the first at pixel (" + std::to_string(f.x) + ", " + std::to_string(f.y) +
           "), sample " + std::to_string(f.sampleIndex);
}

/// The heat palette's five stops (pathlab/images/false_colour.h), as ImGui colours.
ImU32 paletteStop(int stop) {
    unsigned char rgba[4];
    heatColour(static_cast<float>(stop) / 4, rgba);
    return IM_COL32(rgba[0], rgba[1], rgba[2], 255);
}

/// The map view's scale: the palette as a bar, its ends' values beneath, and what grey means.
void drawScaleBar(const LogScale& scale) {
    const float width = 240, height = 12;
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    ImDrawList* draw = ImGui::GetWindowDrawList();
    for (int segment = 0; segment < 4; ++segment) {
        const ImU32 left = paletteStop(segment), right = paletteStop(segment + 1);
        const float x0 = origin.x + width * static_cast<float>(segment) / 4;
        draw->AddRectFilledMultiColor(ImVec2(x0, origin.y),
                                      ImVec2(x0 + width / 4, origin.y + height), left, right, right,
                                      left);
    }
    ImGui::Dummy(ImVec2(width, height));
    ImGui::Text("%-10s log scale %10s", scaleLabel(scale.low).c_str(),
                scaleLabel(scale.high).c_str());
    ImGui::Text("grey: no value (no noise)");
}

/// The figures of the frame shown and the settings asked for, one line each.
void drawFigures(const Frame& frame, const ViewSettings& settings, ViewMode mode,
                 float medianDifference, const std::optional<LogScale>& mapScale) {
    const ViewSettings& s = frame.settings;
    ImGui::Text("%.2f fps  %.1f ms/frame (median)", perSecond(frame.medianFrameSeconds),
                1000.0 * frame.medianFrameSeconds);
    ImGui::Text("%d spp   %.3g rays/s", frame.stats.spp, frame.raysPerSecond);
    // Beside the frame rate (wall time, what a person waits for), the figure to compare: other
    // programs on the machine change the frame rate, and the samples per CPU-second little.
    ImGui::Text("%.3g samples per CPU-second%s", frame.stats.samplesPerCpuSecond(),
                frame.stats.busyNote().empty() ? "" : "  (machine busy)");
    ImGui::Text("lab %s (%s)", std::string(labName(settings.lab)).c_str(),
                std::string(implementationName(settings.implementation)).c_str());
    ImGui::Text("maxDepth %d   continueProb %.2f", settings.parameters.maxDepth,
                settings.parameters.continueProb);
    ImGui::Text("noise %.4f (relative std. error)  efficiency %s", frame.stats.noise,
                frame.stats.efficiencyText().c_str());
    ImGui::Text("%dx%d  view: %s", s.width, s.height, viewModeName(mode));
    if (mode == ViewMode::Split)
        ImGui::Text("student %d spp | solution %d spp", frame.stats.spp, frame.otherSpp);
    if (mode == ViewMode::Difference)
        ImGui::Text("|image - ref| / ref: black 0, blue .125, green .25, yellow .375, red .5+;"
                    " median %.3f",
                    medianDifference);
    if (isMapMode(mode)) {
        if (mapScale)
            drawScaleBar(*mapScale);
        else
            ImGui::Text("(the map comes with the next frame)");
    }
    if (frame.stats.nonfinitePixels > 0)
        ImGui::TextColored(ImVec4(1, 0.3f, 0.3f, 1), "%d pixels got NaN/inf samples%s",
                           frame.stats.nonfinitePixels, firstNonfiniteText(frame.stats).c_str());
    ImGui::Text("h: help");
}

} // namespace

void ViewerPanel::draw(const Frame& frame, const ViewSettings& settings, ViewMode mode,
                       float medianDifference, const std::optional<LogScale>& mapScale,
                       const std::function<void()>& moreWindows) {
    ImGui_ImplOpenGL2_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.6f);
    ImGui::Begin("PathLab", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
    drawFigures(frame, settings, mode, medianDifference, mapScale);
    ImGui::End();
    if (showHelp_) {
        ImGui::SetNextWindowPos(ImVec2(8, 200), ImGuiCond_FirstUseEver);
        ImGui::Begin("Keys", &showHelp_, ImGuiWindowFlags_AlwaysAutoResize);
        ImGui::TextUnformatted(keyHelp().c_str());
        ImGui::End();
    }
    if (moreWindows) moreWindows();
    if (otherWindows_) otherWindows_();
    ImGui::Render();
    ImGui_ImplOpenGL2_RenderDrawData(ImGui::GetDrawData());
}

} // namespace pathlab::viewer
