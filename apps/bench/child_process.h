#pragma once
/// Running another program and collecting what it printed.

#include <string>
#include <vector>

namespace pathlab::bench {

struct ChildResult {
    int exitStatus = -1; ///< the exit code, or 128 + signal number
    std::string output;  ///< standard output and standard error together
    long peakRssKiB = 0; ///< the child's maximum resident set size (getrusage's ru_maxrss)
};

/// Runs `argv[0]` (searched in PATH when it has no slash) with the arguments `argv[1..]` and
/// waits for it. Throws std::runtime_error if it cannot be started.
ChildResult runChild(const std::vector<std::string>& argv);

/// The full path of `program` found in PATH (or `program` itself if it has a slash and is
/// executable); empty if there is none.
std::string findProgram(const std::string& program);

} // namespace pathlab::bench
