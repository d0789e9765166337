#pragma once
/// The grader's command line: one command and its options.

#include "pathlab/lab_registry.h"

#include <cstdint>
#include <string>
#include <vector>

namespace pathlab::grader {

struct Arguments {
    /// grade (the labs of this build), make-references, submission, batch, merge, help.
    std::string command = "grade";
    std::vector<std::string> inputs; ///< submission: one path; batch: folders/files; merge: folders
    std::vector<Lab> labs{AllLabs.begin(), AllLabs.end()};
    std::string viewer, solutionViewer, scenesDir;
    std::string rubric, references;
    std::string json, junit, gradescope, html, report;
    std::string out;         ///< submission, batch, merge: the output folder
    uint64_t seed = 1;
    int threads = 0;
    bool speed = true;
    bool onlyFigures = false;   ///< make-references: only lab_figures.json
    std::string onlyScene;      ///< make-references: only this rubric scene's reference
    // batch
    int jobs = 1;
    bool force = false;
    int shard = 0, shards = 1;
    // submission, as batch starts it (and run_autograder)
    std::string kit;            ///< compiled lab kit (default: built in the output folder)
    std::string referenceCache; ///< references of --scenes, measured once per batch
    std::string timingLock;
    std::vector<int> timingCpus, workCpus;
};

/// Throws InputError naming the option at fault.
Arguments parseArguments(int argc, char** argv);

extern const char* const usage;

} // namespace pathlab::grader
