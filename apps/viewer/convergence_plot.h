#pragma once
/// The window's convergence section: each frame's relative RMSE (or relMSE) against a
/// reference, log-log against samples per pixel or seconds, with the slope −1/2 guide line, the
/// curves of the earlier runs of this window beside the current one, and the current run's time
/// to unit variance. The figures are runner/convergence_history.h's; this file draws them.

#include "convergence_reference.h"

#include "runner/convergence_history.h"

#include <string>

namespace pathlab {
struct Frame;
} // namespace pathlab

namespace pathlab::viewer {

class ConvergencePlot {
public:
    explicit ConvergencePlot(ConvergenceReference reference) : reference_(std::move(reference)) {}

    /// Measures a new frame against the reference, when there is one of the frame's size.
    void onFrame(const Frame& frame);
    /// Draws the section as a window of its own; call between ImGui's NewFrame and Render.
    void draw();

private:
    void drawControls();
    void drawCurves(float width, float height);
    void drawLegend();

    ConvergenceReference reference_;
    ConvergenceHistory history_;
    ConvergenceMetric metric_ = ConvergenceMetric::RelativeRmse;
    ConvergenceAxis axis_ = ConvergenceAxis::Seconds;
    std::string sizeProblem_; ///< the frame is not the reference's size (a resized window)
};

} // namespace pathlab::viewer
