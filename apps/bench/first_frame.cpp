#include "first_frame.h"

#include "process/child_process.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace pathlab::bench {

namespace {

/// The number after `key` in the viewer's output ("first frame: 123.4 ms after start"), or -1.
double figureAfter(const std::string& output, const std::string& key) {
    const size_t at = output.find(key);
    return at == std::string::npos ? -1 : std::atof(output.c_str() + at + key.size());
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

} // namespace

FirstFrameLatency measureFirstFrame(const std::string& viewer, const BenchScene& scene, int runs) {
    FirstFrameLatency f;
    f.runs = runs;
    f.width = 512, f.height = 512; // the window's default size
    if (runs == 0) {
        f.note = "skipped (--first-frame-runs 0)";
        return f;
    }
    const std::string xvfbRun = findProgram("xvfb-run");
    if (xvfbRun.empty()) {
        f.note = "not measured: xvfb-run was not found (Debian package xvfb)";
        return f;
    }
    std::fprintf(stderr, "bench: the viewer's first frame under Xvfb ...\n");
    std::vector<double> frames, images;
    // -a: a free display number; --frames 2: the second frame ends the run, after the first
    // image has been on screen.
    std::vector<std::string> argv = {xvfbRun, "-a", "-s", "-screen 0 1024x768x24", viewer};
    argv.insert(argv.end(), scene.arguments.begin(), scene.arguments.end());
    for (const char* option :
         {"--lab", "importance", "--solution", "--frames", "2", "--print-frame-rate"})
        argv.push_back(option);
    for (int run = 0; run < runs; ++run) {
        const ChildRun child = runChild(argv, {}, RunLimits{120, 1 << 20, 0});
        const double frame = figureAfter(child.output, "first frame: ");
        const double image = figureAfter(child.output, "first image on screen: ");
        if (child.exitCode != 0 || frame < 0 || image < 0) {
            f.note = "not measured: the viewer under xvfb-run said: " + child.output.substr(0, 400);
            return f;
        }
        frames.push_back(frame);
        images.push_back(image);
    }
    f.firstFrameMs = median(frames);
    f.firstImageMs = median(images);
    f.measured = true;
    return f;
}

} // namespace pathlab::bench
