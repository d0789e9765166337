#include "reports/page_style.h"

#include <algorithm>

namespace pathlab::grader {

namespace {

/// About the width at which a 64 × 64 grading render shows its noise and its tiles' seams; three
/// of them (yours, the reference, the heat map) still fit side by side on the page.
constexpr int RenderDisplayWidth = 256;

} // namespace

std::string pageStyle() {
    // The renders: a whole enlargement factor and `pixelated`, or the browser's smoothing blurs
    // the noise that the student is meant to see; `max-width` shrinks them, never past the page,
    // on a narrow screen. The frame (a grey line around a white margin) outlines a render that
    // is as white as the page.
    return "body{font-family:sans-serif;max-width:1100px;margin:auto}"
           "table{border-collapse:collapse}td,th{padding:4px 10px;text-align:left}"
           "tr:nth-child(even){background:#f4f4f4}"
           ".pass{color:#080}.fail{color:#b00}"
           "pre{background:#f4f4f4;padding:8px;white-space:pre-wrap}"
           "img.render{image-rendering:pixelated;height:auto;max-width:calc(100% - 6px);"
           "padding:2px;border:1px solid #888;background:#fff;vertical-align:top}";
}

std::string renderImage(const std::string& pngBase64, int width, int height) {
    const int scale = std::max(1, RenderDisplayWidth / std::max(1, width));
    return "<img class=\"render\" src=\"data:image/png;base64," + pngBase64 + "\" width=\"" +
           std::to_string(scale * width) + "\" height=\"" + std::to_string(scale * height) +
           "\" alt=\"\">";
}

} // namespace pathlab::grader
