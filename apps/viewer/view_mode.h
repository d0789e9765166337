#pragma once
/// What the window shows of a frame: its image, its difference to --reference, the split view,
/// or a per-pixel map of its noise or its efficiency.

#include <optional>
#include <string>

namespace pathlab::viewer {

/// In the v key's order; the maps came last, after the modes the window had before them.
enum class ViewMode { Image, Difference, Split, Noise, Efficiency };

/// The mode as the panel names it.
const char* viewModeName(ViewMode mode);

/// The mode the v key goes to from `mode`, skipping those this run cannot show: the difference
/// needs a --reference image, the split view the reference solutions (the student release has
/// none).
ViewMode nextViewMode(ViewMode mode, bool hasReference, bool hasSolutions);

/// The mode --view names: image, difference, split, noise or efficiency; none for another word.
std::optional<ViewMode> viewModeNamed(const std::string& word);

/// Whether the mode shows a false-coloured map, whose scale the panel draws.
bool isMapMode(ViewMode mode);

} // namespace pathlab::viewer
