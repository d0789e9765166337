#include "test_support.h"

#include "pathlab/lab_tables.h"
#include "pathlab/this_process.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#if defined(_WIN32)
#define popen _popen
#define pclose _pclose
#else
#include <sys/wait.h>
#endif

namespace pathlab::test {

std::string modelPath(const std::string& name) { return std::string(PATHLAB_MODELS_DIR) + "/" + name; }

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

ProcessResult runViewer(const std::string& arguments) {
    const std::string command = std::string(PATHLAB_VIEWER) + " " + arguments + " 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return {-1, "popen failed"};
    std::string output;
    std::array<char, 4096> buffer;
    for (size_t n; (n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0;)
        output.append(buffer.data(), n);
    const int status = pclose(pipe);
#if defined(_WIN32)
    return {status, output};
#else
    return {WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status), output};
#endif
}

} // namespace pathlab::test
