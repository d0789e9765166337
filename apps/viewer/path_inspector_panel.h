#pragma once
/// The path inspector in the window: a clicked pixel's samples replayed (InspectionJob, on a
/// worker thread), their paths drawn over the image (path_overlay.h), and a panel with the
/// selected sample's table, beside the reference solution's and the first difference where the
/// build has the reference.

#include "inspection_job.h"

#include <optional>

namespace pathlab::viewer {

class PathInspectorPanel {
public:
    PathInspectorPanel(const RenderOptions& options, const RenderScene& scene);

    /// Inspects pixel (x, y) of the image `settings` make (the last request wins).
    void inspect(const ViewSettings& settings, int x, int y);
    /// Takes a finished replay: true when one came (the window must be drawn again). Prints
    /// its summary line and the comparison on stdout, as `viewer --inspect` does.
    bool poll();
    /// A replay runs or waits.
    bool busy() const { return job_.busy(); }

    /// Draws the paths over the image and the panel, inside ImGui's frame. `current` is what
    /// the window shows now: the paths are projected with its camera and size.
    void draw(const ViewSettings& current);

private:
    void drawPanel();

    InspectionJob job_;
    std::optional<WindowInspection> shown_;
    int selectedSample_ = 0;
    bool open_ = true; ///< the panel's close button hides it (and the paths) until the next click
};

} // namespace pathlab::viewer
