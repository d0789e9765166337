#include "window_options.h"

namespace pathlab::viewer {

ExtraOptions windowOptionReaders(WindowOptions& w) {
    return {
        {"spp-per-frame",
         [&w](OptionReader& in, const Token& t) {
             w.sppPerFrame = in.positive(t, "samples per pixel", 4096);
         }},
        {"print-frame-rate", [&w](OptionReader&, const Token&) { w.printFrameRate = true; }},
        {"frames", [&w](OptionReader& in,
                        const Token& t) { w.frames = in.positive(t, "a frame count", 1 << 24); }},
        {"screenshot",
         [&w](OptionReader& in, const Token& t) {
             w.screenshot = in.value(t, "an image file name").text;
         }},
        {"capture-window",
         [&w](OptionReader& in, const Token& t) {
             w.windowCapture = in.value(t, "a .png file name").text;
         }},
        {"reference",
         [&w](OptionReader& in, const Token& t) {
             w.referenceImage = in.value(t, "an image file name").text;
         }},
    };
}

void completeWindowOptions(WindowOptions& w) {
    if ((!w.screenshot.empty() || !w.windowCapture.empty()) && w.frames == 0) w.frames = 16;
}

const char* windowOptionsHelp() {
    return R"(window
  --spp-per-frame N      samples per pixel added each frame (default 1)
  --print-frame-rate     print the panel's figures every frame: median frame rate, spp,
                         rays/s, noise, efficiency; and when the first frame arrived and the
                         first image was on screen, in ms after the program started
  --frames N --screenshot FILE
                         run N frames, save the image, quit
  --capture-window FILE.png
                         with --frames: also save the window as shown, panel included
  --reference FILE.exr   image for the difference view
)";
}

} // namespace pathlab::viewer
