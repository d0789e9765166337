#pragma once
/// The window's convergence section: each frame's relative RMSE (or relMSE) against a
/// reference, log-log against samples per pixel or seconds, with the slope −1/2 guide line, the
/// curves of the earlier runs of this window beside the current one, and the current run's time
/// to unit variance. The figures are runner/convergence_history.h's; this file draws them.

#include "convergence_reference.h"

#include "runner/convergence_history.h"

#include "pathlab/scene_io/camera.h"

#include <string>
#include <utility>

namespace pathlab {
struct Frame;
} // namespace pathlab

namespace pathlab::viewer {

class ConvergencePlot {
public:
    /// `camera` is the view the reference shows: the scene's, where the window starts.
    ConvergencePlot(ConvergenceReference reference, const CameraSettings& camera)
        : reference_(std::move(reference)), camera_(camera) {}

    /// Measures a new frame against the reference, when there is one of the frame's size and
    /// the frame is of the reference's view.
    void onFrame(const Frame& frame);
    /// Draws the section as a window of its own; call between ImGui's NewFrame and Render.
    void draw();

private:
    void drawControls();
    void drawCurves(float width, float height);
    void drawLegend();

    ConvergenceReference reference_;
    CameraSettings camera_;
    ConvergenceHistory history_;
    ConvergenceMetric metric_ = ConvergenceMetric::RelativeRmse;
    ConvergenceAxis axis_ = ConvergenceAxis::Seconds;
    /// Why the newest frame is not plotted: not the reference's size (a resized window) or view
    /// (a moved camera); "" when it is.
    std::string notPlotted_;
};

} // namespace pathlab::viewer
