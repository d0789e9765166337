#include "path_inspector_panel.h"

#include "path_overlay.h"

#include "runner/lab_tables.h"

#include "pathlab/inspect/inspection_table.h"

#include <imgui.h>

#include <cstdio>
#include <sstream>
#include <string>

namespace pathlab::viewer {

namespace {

/// The divergence's vertex when it is in `sample`; -1 otherwise.
int divergingVertex(const PixelReplay& replay, size_t sample) {
    if (!replay.comparison || !replay.comparison->divergence) return -1;
    const PathDivergence& d = *replay.comparison->divergence;
    return d.sample == sample ? d.vertex : -1;
}

/// The text table of one sample (pathlab/inspect/inspection_table.h, as `viewer --inspect` prints
/// it), its row of `marked` in the divergence's colour. ImGui's font has no arrow: "->" instead.
void drawSampleTable(const PixelInspection& inspection, size_t sample, int marked) {
    PixelInspection one = inspection;
    one.samples = {inspection.samples[sample]};
    std::istringstream lines(inspectionTable(one));
    const ImVec4 markColour = ImGui::ColorConvertU32ToFloat4(divergenceColour());
    std::string line;
    std::getline(lines, line); // the lab, pixel and seed: the panel's first line says them
    while (std::getline(lines, line)) {
        for (size_t arrow; (arrow = line.find("→")) != std::string::npos;)
            line.replace(arrow, std::string("→").size(), "->");
        int vertex = -1;
        const bool row = line.rfind("  ", 0) == 0 && std::sscanf(line.c_str(), "%d", &vertex) == 1;
        if (row && vertex == marked)
            ImGui::TextColored(markColour, "%s", line.c_str());
        else
            ImGui::TextUnformatted(line.c_str());
    }
}

} // namespace

PathInspectorPanel::PathInspectorPanel(const RenderOptions& options, const RenderScene& scene)
    : job_(options, scene) {}

void PathInspectorPanel::inspect(const ViewSettings& settings, int x, int y) {
    job_.request(settings, x, y);
    open_ = true;
}

bool PathInspectorPanel::poll() {
    std::optional<WindowInspection> finished = job_.takeFinished();
    if (!finished) return false;
    shown_ = std::move(finished);
    const size_t samples = shown_->replay.lab.samples.size();
    if (static_cast<size_t>(selectedSample_) >= samples) selectedSample_ = 0;
    if (!shown_->error.empty())
        std::printf("inspect pixel (%d, %d): %s\n", shown_->x, shown_->y, shown_->error.c_str());
    else
        std::printf("inspected pixel (%d, %d): %zu sample(s), lab %s\n%s", shown_->x, shown_->y,
                    samples, labAndImplementation(shown_->replay.lab.identity).c_str(),
                    pixelReplayText(shown_->replay, false).c_str());
    std::fflush(stdout);
    return true;
}

void PathInspectorPanel::draw(const ViewSettings& current) {
    if (!open_ || (!shown_ && !busy())) return;
    if (shown_ && shown_->error.empty()) {
        const ImGuiIO& io = ImGui::GetIO();
        const float pixelsToScreen =
            io.DisplayFramebufferScale.x > 0 ? 1 / io.DisplayFramebufferScale.x : 1;
        const size_t sample = static_cast<size_t>(selectedSample_);
        drawPathOverlay(ImGui::GetBackgroundDrawList(),
                        {&shown_->replay.lab, sample, divergingVertex(shown_->replay, sample)},
                        CameraProjection(current.camera, current.width, current.height),
                        pixelsToScreen);
    }
    drawPanel();
}

void PathInspectorPanel::drawPanel() {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(8, display.y * 0.55f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(display.x - 16, display.y * 0.45f - 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.7f);
    ImGui::Begin("Path inspector", &open_, ImGuiWindowFlags_HorizontalScrollbar);
    if (busy()) ImGui::Text("replaying the pixel's samples ...");
    if (shown_) {
        const PixelReplay& replay = shown_->replay;
        if (!shown_->error.empty()) {
            ImGui::TextColored(ImVec4(1, 0.3f, 0.3f, 1), "pixel (%d, %d): %s", shown_->x, shown_->y,
                               shown_->error.c_str());
        } else if (!replay.lab.samples.empty()) {
            const RenderIdentity& identity = replay.lab.identity;
            ImGui::Text("pixel (%d, %d)  lab %s  seed %llu", shown_->x, shown_->y,
                        labAndImplementation(identity).c_str(),
                        static_cast<unsigned long long>(identity.seed));
            ImGui::SetNextItemWidth(160);
            ImGui::SliderInt("sample", &selectedSample_, 0,
                             static_cast<int>(replay.lab.samples.size()) - 1);
            ImGui::SameLine(0, 16);
            ImGui::Text("maxDepth %d  continueProb %.2f", identity.parameters.maxDepth,
                        identity.parameters.continueProb);
            drawRayLegend(replay.comparison.has_value());
            const size_t sample = static_cast<size_t>(selectedSample_);
            const int marked = divergingVertex(replay, sample);
            if (replay.comparison)
                ImGui::TextWrapped("%s",
                                   describeComparison(*replay.comparison, replay.lab).c_str());
            ImGui::Separator();
            if (replay.reference) ImGui::TextUnformatted("Your lab:");
            drawSampleTable(replay.lab, sample, marked);
            if (replay.reference && sample < replay.reference->samples.size()) {
                ImGui::Separator();
                ImGui::TextUnformatted("The reference solution, on the same random numbers:");
                drawSampleTable(*replay.reference, sample, marked);
            }
        }
    }
    ImGui::TextDisabled("click a pixel (without moving the mouse) or shift+click: inspect it");
    ImGui::End();
}

} // namespace pathlab::viewer
