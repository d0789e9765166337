#include "inspection_job.h"

#include "pathlab/render/render_scene.h"

#include <chrono>
#include <exception>

namespace pathlab::viewer {

namespace {

/// The options of a render the window made with `settings`, inspecting (x, y).
RenderOptions replayOptions(RenderOptions options, const ViewSettings& settings, int x, int y) {
    static_cast<RenderIdentity&>(options) = settings; // what the window rendered
    options.inspect = true;
    options.inspectX = x;
    options.inspectY = y;
    return options;
}

WindowInspection replay(const RenderOptions& options, const RenderScene& scene,
                        const ViewSettings& settings, int x, int y) {
    WindowInspection inspection{settings, x, y, {}, {}};
    try {
        inspection.replay =
            replayPixel(replayOptions(options, settings, x, y), scene, settings.camera);
    } catch (const std::exception& e) {
        inspection.error = e.what();
    }
    return inspection;
}

} // namespace

InspectionJob::InspectionJob(const RenderOptions& options, const RenderScene& scene)
    : options_(options), scene_(scene) {}

// A replay still running is waited for (the future's destructor would too): it reads the scene.
InspectionJob::~InspectionJob() {
    if (running_.valid()) running_.wait();
}

void InspectionJob::request(const ViewSettings& settings, int x, int y) {
    if (running_.valid())
        waiting_ = Request{settings, x, y};
    else
        start(Request{settings, x, y});
}

void InspectionJob::start(const Request& r) {
    running_ = std::async(std::launch::async, replay, std::cref(options_), std::cref(scene_),
                          r.settings, r.x, r.y);
}

std::optional<WindowInspection> InspectionJob::takeFinished() {
    if (!running_.valid() ||
        running_.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
        return std::nullopt;
    WindowInspection finished = running_.get();
    if (waiting_) {
        start(*waiting_);
        waiting_.reset();
        return std::nullopt; // a newer click replaces it
    }
    return finished;
}

} // namespace pathlab::viewer
