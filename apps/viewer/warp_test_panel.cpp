#include "warp_test_panel.h"

#include "pathlab/render/render_identity.h"
#include "pathlab/support/input_error.h"

#include <imgui.h>

#include <cstdio>

namespace pathlab::viewer {

namespace {

/// Directions per exponent: enough for the test to see a wrong routine, few enough to keep the
/// window responsive (the headless test draws a million).
constexpr uint64_t PanelSamples = 200000;
/// Screen pixels per cell side, and between panels.
constexpr float Cell = 3, Gap = 8;

/// One panel of the test's cells at the cursor, coloured as the picture colours them.
void drawCells(const WarpTestResult& result, WarpPanel panel) {
    const SphereCells& cells = result.settings.cells;
    ImDrawList* list = ImGui::GetWindowDrawList();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const double scale = warpCountScale(result);
    for (int cell = 0; cell < cells.count(); ++cell) {
        unsigned char c[4];
        warpCellColour(result, panel, static_cast<size_t>(cell), scale, c);
        const ImVec2 from(origin.x + (cell % cells.phiCells) * Cell,
                          origin.y + cells.thetaRow(cell) * Cell);
        list->AddRectFilled(from, ImVec2(from.x + Cell, from.y + Cell),
                            IM_COL32(c[0], c[1], c[2], 255));
    }
    ImGui::Dummy(ImVec2(cells.phiCells * Cell, cells.thetaCells * Cell));
}

void drawExponent(const LabWarpTest& test) {
    ImGui::Text("exponent %g: %s", test.exponent, test.result.passed ? "passed" : "FAILED");
    drawCells(test.result, WarpPanel::Observed);
    ImGui::SameLine(0, Gap);
    drawCells(test.result, WarpPanel::Expected);
    ImGui::SameLine(0, Gap);
    drawCells(test.result, WarpPanel::Difference);
}

} // namespace

void WarpTestPanel::run(Lab lab, Implementation implementation) {
    open_ = true;
    tests_.reset();
    try {
        tests_ = runLabWarpTests(lab, implementation, 1, PanelSamples, watchdogSeconds_);
        text_ = describeLabWarpTests(*tests_);
    } catch (const InputError& e) {
        text_ = e.what();
    }
    std::printf("warp test: %s", text_.c_str());
    if (text_.empty() || text_.back() != '\n') std::printf("\n");
    std::fflush(stdout);
}

void WarpTestPanel::draw() {
    if (!open_) return;
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.35f, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.85f);
    ImGui::Begin("Warp test", &open_, ImGuiWindowFlags_AlwaysAutoResize);
    // Wrapped to the width of the three panels, so that the window fits beside the figures.
    const SphereCells cells;
    ImGui::PushTextWrapPos(ImGui::GetCursorPos().x + 3 * cells.phiCells * Cell + 2 * Gap);
    if (tests_) {
        RenderIdentity identity;
        identity.lab = tests_->lab;
        identity.implementation = tests_->implementation;
        ImGui::TextWrapped("lab %s: %llu directions per exponent from sampleLobe, counted over "
                           "the sphere",
                           labAndImplementation(identity).c_str(),
                           static_cast<unsigned long long>(PanelSamples));
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
        ImGui::TextWrapped("theta down from the lobe's axis (0 to 180 degrees), phi across; "
                           "counted | lobePdf's expectation | difference (blue fewer, red more)");
        ImGui::PopStyleColor();
        for (const LabWarpTest& test : tests_->exponents) drawExponent(test);
    }
    ImGui::TextUnformatted(text_.c_str());
    ImGui::PopTextWrapPos();
    ImGui::End();
}

} // namespace pathlab::viewer
