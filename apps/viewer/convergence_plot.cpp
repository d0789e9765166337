#include "convergence_plot.h"

#include "runner/progressive_renderer.h"

#include "pathlab/images/relative_mse.h"

#include <imgui.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace pathlab::viewer {

namespace {

/// A run in words: what resets accumulation and changes the estimator (the lab, whose code,
/// and the parameter that lab uses), as the legend names it.
std::string runLabel(const ViewSettings& s) {
    char parameter[64];
    if (isDepthLimited(s.lab))
        std::snprintf(parameter, sizeof parameter, "maxDepth %d", s.parameters.maxDepth);
    else
        std::snprintf(parameter, sizeof parameter, "continueProb %.2f", s.parameters.continueProb);
    return std::string(labName(s.lab)) + " (" + std::string(implementationName(s.implementation)) +
           "), " + parameter;
}

/// A colour per run, told apart on the dark panel (the Dark2 palette, brightened).
ImU32 runColour(size_t run) {
    static const ImU32 colours[] = {IM_COL32(27, 200, 150, 255),  IM_COL32(255, 127, 14, 255),
                                    IM_COL32(150, 140, 255, 255), IM_COL32(240, 60, 160, 255),
                                    IM_COL32(130, 210, 40, 255),  IM_COL32(240, 200, 20, 255),
                                    IM_COL32(200, 150, 80, 255),  IM_COL32(200, 200, 200, 255)};
    return colours[run % (sizeof colours / sizeof colours[0])];
}

/// "1e-03"-style decade labels read badly at this size; "0.001", "10", "1e+04" read well.
std::string decadeLabel(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

/// A dashed straight line, which ImGui's draw list does not have.
void dashedLine(ImDrawList* draw, ImVec2 a, ImVec2 b, ImU32 colour) {
    const float dx = b.x - a.x, dy = b.y - a.y;
    const float length = std::sqrt(dx * dx + dy * dy);
    const float dash = 5, gap = 4;
    for (float t = 0; t < length; t += dash + gap) {
        const float t1 = std::fmin(t + dash, length);
        draw->AddLine(ImVec2(a.x + dx * t / length, a.y + dy * t / length),
                      ImVec2(a.x + dx * t1 / length, a.y + dy * t1 / length), colour, 1.0f);
    }
}

bool sameView(const CameraSettings& a, const CameraSettings& b) {
    const auto same = [](const Vec3& u, const Vec3& v) {
        return u.x == v.x && u.y == v.y && u.z == v.z;
    };
    return same(a.position, b.position) && same(a.lookAt, b.lookAt) && same(a.up, b.up) &&
           a.fovDegrees == b.fovDegrees && a.leftHanded == b.leftHanded;
}

const char* metricName(ConvergenceMetric metric) {
    return metric == ConvergenceMetric::RelMse ? "relMSE" : "relative RMSE";
}

} // namespace

void ConvergencePlot::onFrame(const Frame& frame) {
    if (reference_.image.width == 0 || frame.image.empty()) return;
    const ViewSettings& s = frame.settings;
    if (s.width != reference_.image.width || s.height != reference_.image.height) {
        notPlotted_ = "the image is " + std::to_string(s.width) + "x" + std::to_string(s.height) +
                      ", the reference " + std::to_string(reference_.image.width) + "x" +
                      std::to_string(reference_.image.height) +
                      ": back to that size for the plot to go on";
        return;
    }
    // Another view's error against the reference would be the difference of two pictures, not
    // noise: those frames are left out until the camera is back.
    if (!sameView(s.camera, camera_)) {
        notPlotted_ = "the camera moved: the reference shows the scene's own view, which the "
                      "plot waits for (restart the viewer to return to it)";
        return;
    }
    notPlotted_.clear();
    ConvergencePoint point;
    point.spp = frame.stats.spp;
    point.seconds = frame.stats.seconds;
    point.relMse = relativeMse(frame.image, reference_.image.rgb);
    point.relativeRmse = relativeRmse(frame.image, reference_.image.rgb);
    history_.add(runLabel(s), point);
}

void ConvergencePlot::draw() {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    if (reference_.image.width == 0) {
        // Folded into its title bar in the top right corner, clear of the image the other views
        // show (the maps, the difference): a click unfolds how to make a reference.
        ImGui::SetNextWindowPos(ImVec2(display.x - 8, 8), ImGuiCond_Always, ImVec2(1, 0));
        ImGui::SetNextWindowCollapsed(true, ImGuiCond_FirstUseEver);
        ImGui::SetNextWindowBgAlpha(0.75f);
        if (ImGui::Begin("Convergence: no reference", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
            ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + 240);
            ImGui::TextUnformatted(reference_.missing.c_str());
            ImGui::PopTextWrapPos();
        }
        ImGui::End();
        return;
    }
    // Kept in the bottom right corner, clear of the panel: its size changes with its legend.
    ImGui::SetNextWindowPos(ImVec2(display.x - 8, display.y - 8), ImGuiCond_Always, ImVec2(1, 1));
    ImGui::SetNextWindowBgAlpha(0.75f);
    ImGui::Begin("Convergence", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
    drawControls();
    drawCurves(300, 170);
    drawLegend();
    if (!notPlotted_.empty())
        ImGui::TextColored(ImVec4(1, 0.6f, 0.3f, 1), "%s", notPlotted_.c_str());
    ImGui::End();
}

void ConvergencePlot::drawControls() {
    int metric = static_cast<int>(metric_), axis = static_cast<int>(axis_);
    ImGui::RadioButton("rel. RMSE", &metric, static_cast<int>(ConvergenceMetric::RelativeRmse));
    ImGui::SameLine();
    ImGui::RadioButton("relMSE", &metric, static_cast<int>(ConvergenceMetric::RelMse));
    ImGui::SameLine();
    ImGui::TextDisabled("|");
    ImGui::SameLine();
    ImGui::RadioButton("seconds", &axis, static_cast<int>(ConvergenceAxis::Seconds));
    ImGui::SameLine();
    ImGui::RadioButton("spp", &axis, static_cast<int>(ConvergenceAxis::SamplesPerPixel));
    metric_ = static_cast<ConvergenceMetric>(metric);
    axis_ = static_cast<ConvergenceAxis>(axis);
}

void ConvergencePlot::drawCurves(float width, float height) {
    const float left = 44, bottom = 18; // room for the decades' labels
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const ImVec2 low(origin.x + left, origin.y + height - bottom), high(origin.x + width, origin.y);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const LogRange x = history_.axisRange(axis_), y = history_.metricRange(metric_);
    const auto at = [&](double xv, double yv) {
        return ImVec2(low.x + (high.x - low.x) * static_cast<float>(x.position(xv)),
                      low.y + (high.y - low.y) * static_cast<float>(y.position(yv)));
    };
    draw->AddRectFilled(ImVec2(low.x, high.y), ImVec2(high.x, low.y), IM_COL32(20, 20, 20, 200));
    const ImU32 grid = IM_COL32(90, 90, 90, 255), text = IM_COL32(200, 200, 200, 255);
    for (double d = x.low; d <= x.high * 1.001; d *= 10) {
        const ImVec2 p = at(d, y.low);
        draw->AddLine(ImVec2(p.x, low.y), ImVec2(p.x, high.y), grid);
        const std::string label = decadeLabel(d);
        draw->AddText(ImVec2(p.x - 4 * label.size(), low.y + 2), text, label.c_str());
    }
    for (double d = y.low; d <= y.high * 1.001; d *= 10) {
        const ImVec2 p = at(x.low, d);
        draw->AddLine(ImVec2(low.x, p.y), ImVec2(high.x, p.y), grid);
        const std::string label = decadeLabel(d);
        draw->AddText(ImVec2(origin.x, p.y - 7), text, label.c_str());
    }
    draw->PushClipRect(ImVec2(low.x, high.y), ImVec2(high.x, low.y), true);
    const LogLine guide = history_.guideLine(axis_, metric_, x);
    if (guide.x1 > 0)
        dashedLine(draw, at(guide.x0, guide.y0), at(guide.x1, guide.y1),
                   IM_COL32(230, 230, 230, 200));
    const auto& runs = history_.runs();
    for (size_t r = 0; r < runs.size(); ++r) {
        std::vector<ImVec2> line;
        for (const ConvergencePoint& p : runs[r].points)
            if (axisValue(p, axis_) > 0 && metricValue(p, metric_) > 0)
                line.push_back(at(axisValue(p, axis_), metricValue(p, metric_)));
        const bool current = r + 1 == runs.size();
        draw->AddPolyline(line.data(), static_cast<int>(line.size()), runColour(r), 0,
                          current ? 2.5f : 1.5f);
    }
    draw->PopClipRect();
    ImGui::Dummy(ImVec2(width, height));
    ImGui::Text("%s vs %s, log-log; dashed: slope %s", metricName(metric_),
                axis_ == ConvergenceAxis::Seconds ? "seconds" : "spp",
                metric_ == ConvergenceMetric::RelMse ? "-1" : "-1/2");
}

void ConvergencePlot::drawLegend() {
    const auto& runs = history_.runs();
    for (size_t r = 0; r < runs.size(); ++r) {
        const ConvergencePoint& last = runs[r].points.back();
        ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(runColour(r)), "%s%s: %.3g at %.3g %s",
                           r + 1 == runs.size() ? "> " : "  ", runs[r].label.c_str(),
                           metricValue(last, metric_), axisValue(last, axis_),
                           axis_ == ConvergenceAxis::Seconds ? "s" : "spp");
    }
    if (const ConvergenceRun* run = history_.current())
        ImGui::Text("time to unit variance (1/efficiency): %.3g s",
                    timeToUnitVariance(run->points.back()));
    ImGui::TextDisabled("against %s", reference_.file.c_str());
}

} // namespace pathlab::viewer
