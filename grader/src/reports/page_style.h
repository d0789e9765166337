#pragma once
/// What the grader's HTML pages share: the feedback page (writeHtmlReport) and a batch's
/// summary.html (writeGradebook) look alike and show renders the same way.

#include <string>

namespace pathlab::grader {

/// The pages' style sheet, without the <style> element around it.
std::string pageStyle();

/// An <img> of a render (`pngBase64`, a PNG of width × height pixels, base64-encoded) enlarged by
/// a whole factor to about 256 CSS pixels wide, its pixels kept square and sharp, and framed so
/// that a near-white render (a furnace) stands out from the white page.
std::string renderImage(const std::string& pngBase64, int width, int height);

} // namespace pathlab::grader
