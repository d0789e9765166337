#pragma once
/// The path inspector: one pixel's first samples replayed through a lab, path by path, with what
/// the lab received at each vertex and the weight it gave it.

#include "pathlab/inspect/inspected_path.h"
#include "pathlab/render/render_identity.h"
#include "pathlab/render/renderer.h"

#include <cstdint>
#include <string>

namespace pathlab {

class Camera;
class RenderProgress;
class RenderScene;

struct InspectionRequest {
    /// The render whose pixel is replayed: its lab, whose code, parameters and seed, and its
    /// width, which numbers the pixels' random streams.
    RenderIdentity identity;
    int x = 0, y = 0; ///< the pixel, (0,0) top left
    int samples = 8;  ///< its samples 0 … samples-1, as a render of any spp draws them
    /// Told of each replay finished, for a watchdog: a lab that never returns hangs a replay
    /// as it hangs a render (null: nobody watches).
    RenderProgress* progress = nullptr;
};

/// Replays the pixel's samples with the random numbers a render gives them, recording every
/// trace() and directLight() the lab makes. The lab's weight of the light found at each vertex
/// (its throughput) is measured, not assumed: each sample is replayed once more per vertex with
/// that vertex's direct light (and once with its emission) changed, and the change of the
/// sample's value divided by the change given. No code of the lab is read, so this works for any
/// lab whose value is linear in the light it receives, as a path tracer's is.
PixelInspection inspectPixel(const RenderScene& scene, const Camera& camera,
                             PathTraceFunction pathTrace, const InspectionRequest& request);

} // namespace pathlab
