#include "isolation/time_limit.h"

#include <algorithm>
#include <cstdio>

namespace pathlab::grader {

double scaledTimeLimit(double rubricSeconds, double startupNow, double startupStored) {
    if (!(startupNow > 0) || !(startupStored > 0)) return rubricSeconds;
    return rubricSeconds * std::clamp(startupNow / startupStored, 1.0, MaxSlowness);
}

std::string timeLimitNote(double rubricSeconds, double scaledSeconds) {
    const double slowness = scaledSeconds / rubricSeconds;
    char note[200];
    std::snprintf(note, sizeof note,
                  "renders run %.1f times slower here now than when the references were made: "
                  "each render may take %.0f s (the rubric's %.0f s × %.2f)",
                  slowness, scaledSeconds, rubricSeconds, slowness);
    return note;
}

} // namespace pathlab::grader
