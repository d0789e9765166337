#pragma once
/// The progressive path-tracing window.

#include "pathlab/render/render_options.h"
#include "window_options.h"

/// Opens the window and runs until it is closed (or --frames are done). Returns the exit status;
/// without a display it says so and returns 2.
int runViewerWindow(const pathlab::RenderOptions& options,
                    const pathlab::viewer::WindowOptions& window);
