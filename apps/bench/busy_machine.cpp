#include "busy_machine.h"

#include "pathlab/render/renderer.h"

#include <algorithm>
#include <cstdio>

namespace pathlab::bench {

namespace {

/// Below this share the cores were shared with other work; above, the threads' hand-offs and
/// the last tasks of a run account for the rest (as the viewer's busy note judges a render).
constexpr double BusyShare = 0.8;
/// A shorter run's share is mostly its threads waking up and its last tasks.
constexpr double LeastSeconds = 0.02;

} // namespace

double CpuUse::share() const {
    const int cores = std::min(threads, Renderer::defaultThreads());
    return cpuSeconds > 0 && seconds > 0 && cores > 0 ? cpuSeconds / (seconds * cores) : 0;
}

std::string busyNote(const std::vector<CpuUse>& measurements) {
    const CpuUse* least = nullptr;
    for (const CpuUse& m : measurements)
        if (m.seconds >= LeastSeconds && m.share() > 0 && (!least || m.share() < least->share()))
            least = &m;
    if (!least || least->share() >= BusyShare) return "";
    const int cores = std::min(least->threads, Renderer::defaultThreads());
    char text[300];
    std::snprintf(text, sizeof text,
                  "the machine was busy: %s had %.0f%% of %d core%s (%.3g s of CPU time in %.3g "
                  "s); the CPU-time figures change little with that, the wall-clock ones do",
                  least->what.c_str(), 100 * least->share(), cores, cores == 1 ? "" : "s",
                  least->cpuSeconds, least->seconds);
    return text;
}

std::string threadsText(int threads) {
    return std::to_string(threads) + (threads == 1 ? " thread" : " threads");
}

} // namespace pathlab::bench
