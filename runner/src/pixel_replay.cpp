#include "runner/pixel_replay.h"

#include "runner/lab_tables.h"

#include "pathlab/scene_io/camera.h"
#include "pathlab/support/input_error.h"
#include "pathlab/inspect/inspection_table.h"
#include "pathlab/inspect/pixel_inspector.h"
#include "pathlab/render/render_progress.h"
#include "pathlab/render/render_scene.h"
#include "pathlab/render/lab_crash_line.h"
#include "pathlab/render/render_watchdog.h"
#include "pathlab/support/whole_file.h"

namespace pathlab {

void checkInspectOptions(const RenderOptions& options) {
    if (!options.inspect) {
        if (!options.inspectOut.empty())
            throw InputError("option --inspect-out: needs --inspect X Y, the pixel to inspect");
        return;
    }
    if (options.inspectX < 0 || options.inspectX >= options.width || options.inspectY < 0 ||
        options.inspectY >= options.height)
        throw InputError("option --inspect: pixel (" + std::to_string(options.inspectX) + ", " +
                         std::to_string(options.inspectY) + ") is outside the " +
                         std::to_string(options.width) + "x" + std::to_string(options.height) +
                         " image (X from 0 to " + std::to_string(options.width - 1) +
                         ", Y from 0 to " + std::to_string(options.height - 1) + ")");
    if (!options.inspectOut.empty()) checkWritable(options.inspectOut);
}

std::vector<PixelInspection> inspectLab(const RenderOptions& options, const RenderScene& scene,
                                        const Camera& camera, Implementation implementation,
                                        const std::vector<ReplayedPixel>& pixels, int samples) {
    InspectionRequest request;
    request.identity = options;
    request.identity.implementation = implementation;
    request.samples = samples;
    // A lab that never returns hangs a replay as it hangs a render: the same watchdog ends it,
    // one for all the pixels.
    RenderProgress progress;
    request.progress = &progress;
    const WatchedLab watched{options.lab, implementation};
    const RenderWatchdog watchdog(progress, options.watchdogSeconds, [watched] { return watched; });
    // And one that crashes it (a recursion that never ends) says so as a render's does.
    const LabCrashLine crashLine(watched);
    const PathTraceFunction pathTrace = findPathTrace(options.lab, implementation);
    progress.passStarts(static_cast<uint64_t>(samples) * pixels.size());
    std::vector<PixelInspection> inspections;
    for (const ReplayedPixel& pixel : pixels) {
        request.x = pixel.x;
        request.y = pixel.y;
        inspections.push_back(inspectPixel(scene, camera, pathTrace, request));
    }
    progress.passEnds();
    return inspections;
}

PixelReplay replayPixel(const RenderOptions& options, const RenderScene& scene) {
    return replayPixel(options, scene,
                       scene.scene().camera.value_or(scene.scene().framingCamera()));
}

PixelReplay replayPixel(const RenderOptions& options, const RenderScene& scene,
                        const CameraSettings& cameraSettings) {
    const Camera camera(cameraSettings, options.width, options.height);
    const std::vector<ReplayedPixel> pixel = {{options.inspectX, options.inspectY}};
    PixelReplay replay{
        inspectLab(options, scene, camera, options.implementation, pixel, options.inspectSamples)
            .front(),
        {},
        {}};
    if (options.implementation == Implementation::Student && solution::available()) {
        replay.reference = inspectLab(options, scene, camera, Implementation::Solution, pixel,
                                      options.inspectSamples)
                               .front();
        replay.comparison = comparePaths(replay.lab, *replay.reference);
    }
    return replay;
}

std::string pixelReplayText(const PixelReplay& replay, bool withTables) {
    std::string text;
    if (withTables) {
        text += (replay.lab.identity.implementation == Implementation::Student
                     ? "Your lab: "
                     : "The reference solution: ") +
                inspectionTable(replay.lab);
        if (replay.reference)
            text += "\nThe reference solution: " + inspectionTable(*replay.reference);
        text += "\n";
    }
    if (replay.comparison)
        text += describeComparison(*replay.comparison, replay.lab) + "\n";
    else if (replay.lab.identity.implementation == Implementation::Student)
        text += "The reference solution is not in this build (the student release has none): "
                "the table shows your lab alone.\n";
    return text;
}

} // namespace pathlab
