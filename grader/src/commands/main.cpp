// grader: grades the labs of a build for correctness, noise and speed against the reference
// solutions, and submitted labs in a sandbox, one or a whole class at a time; writes its verdict
// for people and platforms. `grader --help` lists the commands.
#include "checks/grading_scenes.h"
#include "checks/rubric_text.h"
#include "commands/commands.h"

#include "pathlab/support/program_main.h"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <unistd.h>

namespace {

/// The scratch folders of graders that ended without removing theirs (killed, a batch stopped
/// by SIGTERM, whose gradings went with it): each is named after its grader's process, and one
/// whose process is gone is removed by the next grader to start.
void removeScratchOfEndedGraders() {
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator("/tmp", error)) {
        const std::string name = entry.path().filename().string();
        const std::string prefix = "pathlab-grader-";
        if (name.rfind(prefix, 0) != 0) continue;
        const long pid = std::strtol(name.c_str() + prefix.size(), nullptr, 10);
        if (pid <= 0 || ::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;
        std::filesystem::remove_all(entry.path(), error);
    }
}

} // namespace

int main(int argc, char** argv) {
    using namespace pathlab;
    using namespace pathlab::grader;
    std::string scratch;
    // Exit status 3 for an error of the grader's own, told apart from bad input (2) and labs that
    // failed their grade (1).
    const int status = runMain(
        "grader",
        [&] {
            const Arguments a = parseArguments(argc, argv);
            if (a.command == "help") {
                std::fputs(usage().c_str(), stdout);
                return 0;
            }
            if (a.command == "merge") return mergeBatches(a);
            if (a.command == "keep-term") return keepTerm(a);
            const Rubric rubric = loadRubric(a.rubric);
            if (a.command == "rubric" && a.sceneFiles) {
                for (const std::string& file : rubricSceneFiles(rubric))
                    std::printf("%s\n", file.c_str());
                return 0;
            }
            if (a.command == "rubric") {
                rubricSceneFiles(rubric); // a public scene missing from models/ is said now
                const int hidden = a.scenesDir.empty()
                                       ? 0
                                       : static_cast<int>(hiddenScenePaths(a.scenesDir).size());
                std::fputs(rubricText(rubric, a.rubric, hidden).c_str(), stdout);
                return 0;
            }
            if (a.command == "make-variants") return makeVariants(a, rubric);
            removeScratchOfEndedGraders();
            std::string pattern = "/tmp/pathlab-grader-" + std::to_string(::getpid()) + "-XXXXXX";
            if (!::mkdtemp(pattern.data()))
                throw std::runtime_error("cannot make a scratch folder");
            scratch = pattern;
            if (a.command == "make-references") return makeReferences(a, rubric, scratch);
            if (a.command == "submission") return gradeOneSubmission(a, rubric, scratch);
            if (a.command == "batch") return runBatch(a, rubric, scratch);
            if (a.command == "student-variants") return makeStudentVariants(a, rubric, scratch);
            return gradeBuild(a, rubric, scratch);
        },
        3);
    if (!scratch.empty()) std::filesystem::remove_all(scratch);
    return status;
}
