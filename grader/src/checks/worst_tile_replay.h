#pragma once
/// The side-by-side replay in a failed lab's feedback: one pixel of the scene's worst tile, its
/// samples through the lab and through the reference solution on the same random numbers, and
/// the first vertex where they part (pathlab/inspect/path_comparison.h).

#include "checks/grader_setup.h"

#include <string>
#include <vector>

namespace pathlab::grader {

/// The pixel at the centre of the tile whose mean differs most (largest |t|) among the scene's
/// `t` statistics (three whole-image channels, then three per tile, rows from the top).
struct TilePixel {
    int x = 0, y = 0;
};
TilePixel worstTilePixel(const std::vector<double>& t, int tiles, int width, int height);

/// What the replay found: its sentence for the feedback ("" where there is none to give: this
/// build has no reference solutions, the student release, or a replay's render failed), and
/// whether the paths parted.
struct ReplayFinding {
    std::string text;
    bool diverged = false;
};
ReplayFinding replayWorstTile(const GraderSetup& setup, Lab lab, const GradingScene& scene,
                              const std::vector<double>& t, uint64_t seed);

} // namespace pathlab::grader
