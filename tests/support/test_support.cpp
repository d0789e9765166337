#include "test_support.h"

#include "runner/lab_tables.h"

#include "pathlab/support/this_process.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>

namespace pathlab::test {

std::string modelPath(const std::string& name) {
    return std::string(PATHLAB_MODELS_DIR) + "/" + name;
}

std::string temporaryFolder(const std::string& name) {
    namespace fs = std::filesystem;
    const fs::path folder =
        fs::temp_directory_path() / ("pathlab-test-" + std::to_string(processId()) + "-" + name);
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder.string();
}

HeadlessResult render(const std::vector<std::string>& arguments) {
    std::vector<const char*> argv = {"viewer"};
    for (const std::string& a : arguments) argv.push_back(a.c_str());
    if (const char* watchdog = std::getenv("PATHLAB_TEST_WATCHDOG_SECONDS"))
        argv.insert(argv.end(), {"--watchdog", watchdog});
    return renderHeadless(parseRenderOptions(static_cast<int>(argv.size()), argv.data()));
}

HeadlessResult renderLabUnderTest(std::vector<std::string> arguments) {
    if (solution::available()) arguments.push_back("--solution");
    return render(arguments);
}

Estimate estimateOf(const HeadlessResult& result) {
    const RenderStats& s = result.stats;
    const double n = static_cast<double>(s.width) * s.height * s.spp;
    Estimate e;
    e.mean = s.meanRadiance;
    e.standardError = {static_cast<float>(std::sqrt(s.meanVariance.r / n)),
                       static_cast<float>(std::sqrt(s.meanVariance.g / n)),
                       static_cast<float>(std::sqrt(s.meanVariance.b / n))};
    return e;
}

ShellCommandResult runViewer(const std::string& arguments) {
    return runShellCommand(std::string(PATHLAB_VIEWER) + " " + arguments);
}

std::string builtViewer() { return PATHLAB_VIEWER; }

} // namespace pathlab::test
