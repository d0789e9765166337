#include "view_mode.h"

namespace pathlab::viewer {

const char* viewModeName(ViewMode mode) {
    switch (mode) {
    case ViewMode::Image: return "image";
    case ViewMode::Difference: return "difference to --reference";
    case ViewMode::Split: return "split: student left, solution right, equal time";
    case ViewMode::Noise: return "noise: each pixel's relative standard error";
    case ViewMode::Efficiency: return "efficiency: 1 / (relative variance x s per sample)";
    }
    return "?";
}

ViewMode nextViewMode(ViewMode mode, bool hasReference, bool hasSolutions) {
    switch (mode) {
    case ViewMode::Image:
        return hasReference   ? ViewMode::Difference
               : hasSolutions ? ViewMode::Split
                              : ViewMode::Noise;
    case ViewMode::Difference: return hasSolutions ? ViewMode::Split : ViewMode::Noise;
    case ViewMode::Split: return ViewMode::Noise;
    case ViewMode::Noise: return ViewMode::Efficiency;
    case ViewMode::Efficiency: return ViewMode::Image;
    }
    return ViewMode::Image;
}

std::optional<ViewMode> viewModeNamed(const std::string& word) {
    if (word == "image") return ViewMode::Image;
    if (word == "difference") return ViewMode::Difference;
    if (word == "split") return ViewMode::Split;
    if (word == "noise") return ViewMode::Noise;
    if (word == "efficiency") return ViewMode::Efficiency;
    return std::nullopt;
}

bool isMapMode(ViewMode mode) { return mode == ViewMode::Noise || mode == ViewMode::Efficiency; }

} // namespace pathlab::viewer
