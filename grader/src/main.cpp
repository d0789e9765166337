// grader: grades the labs of a build for correctness, noise and speed against the reference
// solutions, and submitted labs in a sandbox, one or a whole class at a time; writes its verdict
// for people and platforms. `grader --help` lists the commands.
#include "commands.h"
#include "grading_scenes.h"
#include "rubric_text.h"

#include "pathlab/input_error.h"

#include <cstdio>
#include <filesystem>
#include <unistd.h>

int main(int argc, char** argv) {
    using namespace pathlab;
    using namespace pathlab::grader;
    std::string scratch;
    int status = 2;
    try {
        const Arguments a = parseArguments(argc, argv);
        if (a.command == "help") {
            std::fputs(usage, stdout);
            return 0;
        }
        if (a.command == "merge") return mergeBatches(a);
        const Rubric rubric = loadRubric(a.rubric);
        if (a.command == "rubric") {
            const int hidden =
                a.scenesDir.empty() ? 0 : static_cast<int>(hiddenScenePaths(a.scenesDir).size());
            std::fputs(rubricText(rubric, a.rubric, hidden).c_str(), stdout);
            return 0;
        }
        char pattern[] = "/tmp/pathlab-grader-XXXXXX";
        if (!::mkdtemp(pattern)) throw std::runtime_error("cannot make a scratch folder");
        scratch = pattern;
        if (a.command == "make-references")
            status = makeReferences(a, rubric, scratch);
        else if (a.command == "submission")
            status = gradeOneSubmission(a, rubric, scratch);
        else if (a.command == "batch")
            status = runBatch(a, rubric, scratch);
        else
            status = gradeBuild(a, rubric, scratch);
    } catch (const InputError& e) {
        std::fprintf(stderr, "grader: %s\n", e.what());
        status = 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "grader: error: %s\n", e.what());
        status = 3;
    }
    if (!scratch.empty()) std::filesystem::remove_all(scratch);
    return status;
}
