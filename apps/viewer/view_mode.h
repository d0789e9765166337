#pragma once
/// What the window shows of a frame: its image, its difference to --reference, or the split view.

namespace pathlab::viewer {

enum class ViewMode { Image, Difference, Split };

/// The mode as the panel names it.
const char* viewModeName(ViewMode mode);

/// The mode the v key goes to from `mode`, skipping those this run cannot show: the difference
/// needs a --reference image, the split view the reference solutions (the student release has
/// none).
ViewMode nextViewMode(ViewMode mode, bool hasReference, bool hasSolutions);

} // namespace pathlab::viewer
