#include "view_mode.h"

namespace pathlab::viewer {

const char* viewModeName(ViewMode mode) {
    switch (mode) {
    case ViewMode::Image: return "image";
    case ViewMode::Difference: return "difference to --reference";
    case ViewMode::Split: return "split: student left, solution right, equal time";
    }
    return "?";
}

ViewMode nextViewMode(ViewMode mode, bool hasReference, bool hasSolutions) {
    if (mode == ViewMode::Image)
        return hasReference   ? ViewMode::Difference
               : hasSolutions ? ViewMode::Split
                              : ViewMode::Image;
    if (mode == ViewMode::Difference && hasSolutions) return ViewMode::Split;
    return ViewMode::Image;
}

} // namespace pathlab::viewer
