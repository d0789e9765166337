#include "path_overlay.h"

#include "pathlab/constants.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace pathlab::viewer {

CameraProjection::CameraProjection(const CameraSettings& camera, int width, int height)
    : eye_(camera.position), width_(static_cast<float>(width)),
      height_(static_cast<float>(height)) {
    // The same frame as pathlab::Camera's constructor (framework/src/scene_io/camera.cpp).
    forward_ = normalize(camera.lookAt - camera.position);
    right_ = normalize(cross(forward_, camera.up));
    up_ = cross(right_, forward_);
    if (camera.leftHanded) right_ = -right_;
    halfHeight_ = std::tan(0.5f * camera.fovDegrees * Pi / 180.0f);
    halfWidth_ = halfHeight_ * width_ / height_;
    near_ = 1e-4f * std::max(length(camera.lookAt - camera.position), 1e-3f);
}

ImVec2 CameraProjection::toPixels(const Vec3& point, float depth) const {
    const Vec3 d = point - eye_;
    const float sx = dot(d, right_) / depth, sy = dot(d, up_) / depth;
    return ImVec2((sx / halfWidth_ + 1) * 0.5f * width_, (1 - sy / halfHeight_) * 0.5f * height_);
}

std::optional<std::pair<ImVec2, ImVec2>> CameraProjection::segment(const Vec3& a,
                                                                   const Vec3& b) const {
    float depthA = dot(a - eye_, forward_), depthB = dot(b - eye_, forward_);
    if (depthA < near_ && depthB < near_) return std::nullopt;
    Vec3 from = a, to = b;
    // A camera ray starts at the eye itself: cut it (and any segment that passes behind the
    // camera) at the near depth, where it still projects.
    if (depthA < near_) {
        from = a + (b - a) * ((near_ - depthA) / (depthB - depthA));
        depthA = near_;
    } else if (depthB < near_) {
        to = a + (b - a) * ((near_ - depthA) / (depthB - depthA));
        depthB = near_;
    }
    return std::make_pair(toPixels(from, depthA), toPixels(to, depthB));
}

ImU32 rayColour(const std::string& arrivedBy) {
    // Away from the Cornell box's red and green walls and its white light.
    if (arrivedBy == "camera") return IM_COL32(255, 255, 255, 255);
    if (arrivedBy == "diffuse") return IM_COL32(255, 200, 0, 255);
    if (arrivedBy == "mirror" || arrivedBy == "specular") return IM_COL32(0, 200, 255, 255);
    if (arrivedBy == "refraction") return IM_COL32(255, 0, 255, 255);
    return IM_COL32(150, 150, 150, 255);
}

ImU32 shadowRayColour() { return IM_COL32(190, 190, 255, 255); }

ImU32 divergenceColour() { return IM_COL32(255, 40, 40, 255); }

void drawRayLegend(bool withDivergence) {
    const auto entry = [](ImU32 colour, const char* text) {
        ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(colour), "%s", text);
        ImGui::SameLine();
    };
    entry(rayColour("camera"), "camera");
    entry(rayColour("diffuse"), "diffuse");
    entry(rayColour("mirror"), "mirror");
    entry(rayColour("refraction"), "refraction");
    entry(shadowRayColour(), "- - shadow ray");
    if (withDivergence) entry(divergenceColour(), "o first difference");
    ImGui::NewLine();
}

namespace {

ImU32 withAlpha(ImU32 colour, int alpha) {
    return (colour & ~IM_COL32_A_MASK) | (static_cast<ImU32>(alpha) << IM_COL32_A_SHIFT);
}

ImVec2 scaled(ImVec2 p, float scale) { return ImVec2(p.x * scale, p.y * scale); }

/// The part of a → b inside the display (Liang-Barsky); false when none is.
bool clipToDisplay(ImVec2& a, ImVec2& b) {
    const ImVec2 size = ImGui::GetIO().DisplaySize;
    const float d[2] = {b.x - a.x, b.y - a.y}, from[2] = {a.x, a.y}, high[2] = {size.x, size.y};
    float t0 = 0, t1 = 1;
    for (int axis = 0; axis < 2; ++axis) {
        if (d[axis] == 0) {
            if (from[axis] < 0 || from[axis] > high[axis]) return false;
            continue;
        }
        float enter = (0 - from[axis]) / d[axis], leave = (high[axis] - from[axis]) / d[axis];
        if (enter > leave) std::swap(enter, leave);
        t0 = std::max(t0, enter);
        t1 = std::min(t1, leave);
    }
    if (t0 > t1) return false;
    const ImVec2 start(a.x + d[0] * t0, a.y + d[1] * t0), end(a.x + d[0] * t1, a.y + d[1] * t1);
    a = start, b = end;
    return true;
}

/// Dashes on the visible part only: a segment that passes close by the eye projects to one far
/// longer than the window, whose dashes would be countless.
void dashedLine(ImDrawList* draw, ImVec2 a, ImVec2 b, ImU32 colour, float thickness) {
    if (!clipToDisplay(a, b)) return;
    const float dash = 6, gap = 4;
    const float dx = b.x - a.x, dy = b.y - a.y, length = std::sqrt(dx * dx + dy * dy);
    if (length <= 0) return;
    for (float s = 0; s < length; s += dash + gap) {
        const float e = std::min(s + dash, length);
        draw->AddLine(ImVec2(a.x + dx * s / length, a.y + dy * s / length),
                      ImVec2(a.x + dx * e / length, a.y + dy * e / length), colour, thickness);
    }
}

/// Where the ray that found `v` started: its parent's position, or the camera's eye.
Vec3 rayStart(const InspectedVertex& v) { return v.ray.origin; }

struct SampleStyle {
    int alpha = 255;
    float thickness = 2;
    /// The draw list's vertices beyond which nothing more is drawn: ImGui's OpenGL 2 backend
    /// indexes a list's vertices with 16 bits (65536 at most, an assertion past it), and many
    /// samples of long or branching paths would pass that.
    int vertexBudget = 60000;
};

/// The other samples, faint, stop well before the budget, which leaves the selected one room.
constexpr int OtherSamplesVertexBudget = 40000;

void drawSample(ImDrawList* draw, const InspectedSample& sample, const CameraProjection& projection,
                float scale, const SampleStyle& style, float stubLength) {
    for (const InspectedVertex& v : sample.vertices) {
        if (draw->VtxBuffer.Size > style.vertexBudget) return;
        const ImU32 colour = withAlpha(rayColour(v.arrivedBy), style.alpha);
        // A ray that left the scene has no end: a short stub shows which way it went.
        const Vec3 end = v.found ? v.position : rayStart(v) + v.ray.direction * stubLength;
        if (const auto s = projection.segment(rayStart(v), end)) {
            draw->AddLine(scaled(s->first, scale), scaled(s->second, scale), colour,
                          style.thickness);
            if (v.found)
                draw->AddCircleFilled(scaled(s->second, scale), style.thickness + 1, colour);
        }
        if (v.shadowRay)
            if (const auto s = projection.segment(v.shadowRay->from, v.shadowRay->to))
                dashedLine(draw, scaled(s->first, scale), scaled(s->second, scale),
                           withAlpha(shadowRayColour(), style.alpha), style.thickness * 0.75f);
    }
}

/// The stubs' length: a fifth of the distance from the first vertex to the eye, so that it
/// reads the same in a scene of any size.
float stubLengthOf(const PixelInspection& inspection) {
    for (const InspectedSample& sample : inspection.samples)
        for (const InspectedVertex& v : sample.vertices)
            if (v.found) return 0.2f * length(v.position - v.ray.origin);
    return 1;
}

} // namespace

void drawPathOverlay(ImDrawList* draw, const OverlayPaths& paths,
                     const CameraProjection& projection, float pixelsToScreen) {
    if (!paths.inspection || paths.inspection->samples.empty()) return;
    const PixelInspection& inspection = *paths.inspection;
    const float stub = stubLengthOf(inspection);
    for (size_t i = 0; i < inspection.samples.size(); ++i)
        if (i != paths.selectedSample)
            drawSample(draw, inspection.samples[i], projection, pixelsToScreen,
                       {70, 1, OtherSamplesVertexBudget}, stub);
    if (paths.selectedSample >= inspection.samples.size()) return;
    const InspectedSample& selected = inspection.samples[paths.selectedSample];
    drawSample(draw, selected, projection, pixelsToScreen, {255, 2}, stub);
    for (const InspectedVertex& v : selected.vertices)
        if (v.index == paths.markedVertex && v.found)
            if (const auto s = projection.segment(v.ray.origin, v.position))
                draw->AddCircle(scaled(s->second, pixelsToScreen), 7, divergenceColour(), 0, 2);
}

} // namespace pathlab::viewer
