#include "window_options.h"

#include "runner/lab_tables.h"

#include "pathlab/support/input_error.h"

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
        {"view",
         [&w](OptionReader& in, const Token& t) {
             const Token& word = in.value(t, "image, difference, split, noise or efficiency");
             w.view = viewModeNamed(word.text);
             if (!w.view)
                 OptionReader::fail(word, "option --view: '" + word.text +
                                              "' is not a view: image, difference, split, noise "
                                              "or efficiency");
         }},
        {"inspect-window", [&w](OptionReader&, const Token&) { w.inspectInWindow = true; }},
        {"warp-panel", [&w](OptionReader&, const Token&) { w.warpPanel = true; }},
    };
}

void completeWindowOptions(WindowOptions& w) {
    if ((!w.screenshot.empty() || !w.windowCapture.empty()) && w.frames == 0) w.frames = 16;
    if (w.view == ViewMode::Difference && w.referenceImage.empty())
        throw InputError("option --view difference: needs --reference FILE.exr");
    if (w.view == ViewMode::Split && !solution::available())
        throw InputError("option --view split: the reference solutions are not part of this "
                         "build");
}

void checkInspectWindow(const WindowOptions& w, const RenderOptions& options) {
    if (!w.inspectInWindow) return;
    if (!options.inspect)
        throw InputError("option --inspect-window: needs --inspect X Y, the pixel to inspect");
    if (!options.outputImage.empty() || !options.inspectOut.empty())
        throw InputError("option --inspect-window: opens the window, which -o and --inspect-out "
                         "do not (leave it out to inspect headless)");
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
  --view MODE            the view shown first: image, difference, split, noise (each
                         pixel's relative standard error) or efficiency (each pixel's
                         1 / (relative variance x seconds per sample)); v cycles on
  --inspect X Y --inspect-window
                         open the window with pixel (X,Y) inspected, as a click does (a
                         click without moving the mouse, or shift+click); --inspect alone
                         replays headless and prints the tables
  --warp-panel           open the window with the lab's warp test shown, as t shows it (lab 5:
                         its sampleLobe's directions against its lobePdf)
)";
}

} // namespace pathlab::viewer
