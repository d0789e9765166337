#include "commands/batch_cores.h"

#include <filesystem>
#include <sched.h>

namespace pathlab::grader {

namespace fs = std::filesystem;

std::vector<int> allowedCpus() {
    cpu_set_t set;
    std::vector<int> cpus;
    if (::sched_getaffinity(0, sizeof set, &set) == 0)
        for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu)
            if (CPU_ISSET(cpu, &set)) cpus.push_back(cpu);
    return cpus;
}

std::string joinCpus(const std::vector<int>& cpus) {
    std::string text;
    for (int cpu : cpus) text += (text.empty() ? "" : ",") + std::to_string(cpu);
    return text;
}

std::string timingLockFor(const std::vector<int>& timingCpus) {
    const std::string core = timingCpus.empty() ? "any" : std::to_string(timingCpus.front());
    return (fs::temp_directory_path() / ("pathlab-timing-core-" + core + ".lock")).string();
}

Cores splitCores(const std::vector<int>& cpus) {
    // Element by element: GCC 14 takes the copy of a vector it knows to be this short for a
    // memmove out of bounds (a false -Warray-bounds).
    Cores cores;
    if (cpus.empty()) return cores; // any core, for both
    cores.timing.push_back(cpus.front());
    if (cpus.size() == 1) cores.work.push_back(cpus.front()); // one core: work shares it
    for (size_t i = 1; i < cpus.size(); ++i) cores.work.push_back(cpus[i]);
    return cores;
}

} // namespace pathlab::grader
