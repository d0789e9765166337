#pragma once
/// Running a command line through the system's shell, on every system the kit builds on
/// (child_process.h is POSIX only): the tests run the viewer this way.

#include <string>

namespace pathlab {

struct ShellCommandResult {
    int exitStatus = -1; ///< its exit status (POSIX: 128 + the signal that ended it)
    std::string output;  ///< standard output and standard error together
};

/// Runs `command` with the shell (POSIX: /bin/sh -c; Windows: cmd.exe, through _popen) and
/// waits for it to end.
ShellCommandResult runShellCommand(const std::string& command);

} // namespace pathlab
