#pragma once
/// What the window tells scripts about its frames: --print-frame-rate's lines and --stats' file.
/// Their texts are read by scripts (the tests, the bench, the grader): keep them as they are.

#include "pathlab/render/render_options.h"

namespace pathlab {
struct Frame;
}

namespace pathlab::viewer {

/// Frames per second from seconds per frame (0 before the first frame).
double perSecond(double seconds);

/// --print-frame-rate: one line per finished frame, with the figures the panel shows, labelled.
void printFrameLine(const Frame& frame);

/// --print-frame-rate: "EVENT: 12.3 ms after start", the first-frame latencies the bench reads.
void printMillisecondsSinceStart(const char* event);

/// --stats for the window: a headless render's fields for the frames shown, with the panel's
/// median frame rate. False, said on stderr, if no frame was finished or the file not written.
bool writeWindowStats(const RenderOptions& options, const Frame& frame);

} // namespace pathlab::viewer
