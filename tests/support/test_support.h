#pragma once
/// Shared by the tests: where the models are, rendering in-process, running the viewer.

#include "runner/headless_render.h"

#include "process/shell_command.h"

#include <filesystem>
#include <string>
#include <vector>

namespace pathlab::test {

/// models/NAME in the source tree.
std::string modelPath(const std::string& name);

/// A fresh empty folder under the system's temporary folder, for files a test writes.
std::string temporaryFolder(const std::string& name);

/// A temporaryFolder removed, with what the test wrote into it, when the test ends.
struct ScratchFolder {
    std::filesystem::path path;
    explicit ScratchFolder(const std::string& name) : path(temporaryFolder(name)) {}
    ~ScratchFolder() { std::filesystem::remove_all(path); }
    ScratchFolder(const ScratchFolder&) = delete;
    ScratchFolder& operator=(const ScratchFolder&) = delete;
};

/// Renders in-process with viewer-style arguments, e.g. {"-c", modelPath(...), "--spp", "4"}.
/// The render's watchdog (pathlab/render/render_watchdog.h) waits its default, or the seconds that
/// the environment variable PATHLAB_TEST_WATCHDOG_SECONDS gives: the kit's test of the lab
/// tests (estimators/catches_mutants.py) shortens it to see it stop an endless loop.
HeadlessResult render(const std::vector<std::string>& arguments);

/// Renders like render() with the labs the lab tests check: the reference solutions where the
/// test executable has them (`--solution`); otherwise its student labs: the student's own labs/
/// in the student release, so that there a lab's tests pass once the student has finished it,
/// and the mutant labs of the kit's test of the lab tests (tests/estimators/CMakeLists.txt).
HeadlessResult renderLabUnderTest(std::vector<std::string> arguments);

/// The image mean and its standard error, averaged over the three channels or per channel:
/// SE² = mean pixel variance / (pixels × spp), since pixels are independent.
struct Estimate {
    Color mean;
    Color standardError;
};
Estimate estimateOf(const HeadlessResult& result);

/// Runs the built viewer with `arguments` (a shell-quoted string); returns its exit status and
/// what it printed on stdout and stderr together.
ShellCommandResult runViewer(const std::string& arguments);

/// The built viewer's path (the one runViewer runs).
std::string builtViewer();

} // namespace pathlab::test
