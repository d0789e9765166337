// grader: grades the labs of a build for correctness, noise and speed against the reference
// solutions, and submitted labs in a sandbox, one or a whole class at a time; writes its verdict
// for people and platforms. `grader --help` lists the commands.
#include "checks/grading_scenes.h"
#include "checks/rubric_text.h"
#include "commands/commands.h"

#include "pathlab/program_main.h"

#include <cstdio>
#include <filesystem>
#include <unistd.h>

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
                std::fputs(usage, stdout);
                return 0;
            }
            if (a.command == "merge") return mergeBatches(a);
            const Rubric rubric = loadRubric(a.rubric);
            if (a.command == "rubric") {
                const int hidden = a.scenesDir.empty()
                                       ? 0
                                       : static_cast<int>(hiddenScenePaths(a.scenesDir).size());
                std::fputs(rubricText(rubric, a.rubric, hidden).c_str(), stdout);
                return 0;
            }
            if (a.command == "make-variants") return makeVariants(a, rubric);
            char pattern[] = "/tmp/pathlab-grader-XXXXXX";
            if (!::mkdtemp(pattern)) throw std::runtime_error("cannot make a scratch folder");
            scratch = pattern;
            if (a.command == "make-references") return makeReferences(a, rubric, scratch);
            if (a.command == "submission") return gradeOneSubmission(a, rubric, scratch);
            if (a.command == "batch") return runBatch(a, rubric, scratch);
            return gradeBuild(a, rubric, scratch);
        },
        3);
    if (!scratch.empty()) std::filesystem::remove_all(scratch);
    return status;
}
