#include "process/shell_command.h"

#if defined(_WIN32)
#include <array>
#include <cstdio>
#else
#include "process/child_process.h"
#endif

namespace pathlab {

#if defined(_WIN32)

// Windows, where nothing but the viewer, the labs and their tests is built (no grader, no
// fork): the C runtime's _popen.
ShellCommandResult runShellCommand(const std::string& command) {
    FILE* pipe = _popen((command + " 2>&1").c_str(), "r");
    if (!pipe) return {-1, "popen failed"};
    std::string output;
    std::array<char, 4096> buffer;
    for (size_t n; (n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0;)
        output.append(buffer.data(), n);
    return {_pclose(pipe), output};
}

#else

ShellCommandResult runShellCommand(const std::string& command) {
    const ChildRun run = runChild({"/bin/sh", "-c", command});
    if (!run.started) return {-1, "could not start /bin/sh"};
    return {run.exitCode, run.output};
}

#endif

} // namespace pathlab
