#pragma once
/// A whole headless render: load, trace, measure. The viewer's -o and the grader share it.

#include "pathlab/render/accumulation_buffer.h"
#include "pathlab/render/render_options.h"
#include "pathlab/render/render_stats.h"

namespace pathlab {

struct HeadlessResult {
    AccumulationBuffer image;
    RenderStats stats;
};

class RenderScene;

/// Renders options.spp samples per pixel of the scene the options name, with the lab and
/// implementation they choose. Throws InputError for a bad scene.
HeadlessResult renderHeadless(const RenderOptions& options);

/// The same with the scene already loaded (several seeds of one scene: viewer --seeds).
HeadlessResult renderHeadless(const RenderOptions& options, const RenderScene& scene);

} // namespace pathlab
