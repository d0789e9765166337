#pragma once
/// The grader's command line: one command and its options.

#include "pathlab/render/lab_registry.h"

#include <cstdint>
#include <string>
#include <vector>

namespace pathlab::grader {

struct Arguments {
    /// grade (the labs of this build), make-references, submission, batch, merge, rubric, help.
    std::string command = "grade";
    std::vector<std::string> inputs; ///< submission: one path; batch: folders/files; merge: folders
    std::vector<Lab> labs{AllLabs.begin(), AllLabs.end()};
    std::string viewer, solutionViewer;
    /// The hidden scenes: grader/hidden_scenes/ when it holds any, or --scenes DIR; "" for none.
    std::string scenesDir;
    bool scenesNone = false; ///< --scenes none: the public scenes only, no variants either
    /// batch, make-variants: the seed of the scene variants (scene_variants.h); 0: the one an
    /// earlier batch into --out kept, else a new one.
    uint64_t variantSeed = 0;
    bool revealHidden = false; ///< feedback may name hidden scenes and show their images
    /// grade: a student's variant folder (student_variant.h) to grade on as well.
    std::string variant;
    std::string rubric, references;
    bool rubricGiven = false;     ///< --rubric on the command line (else the kit's)
    bool referencesGiven = false; ///< --references on the command line (else the kit's)
    std::string json, junit, gradescope, prairielearn, html, report;
    /// --report: where `make sweep` wrote its plots (default: sweep/ beside the grader).
    std::string sweeps;
    std::string out; ///< submission, batch, merge: the output folder
    uint64_t seed = 1;
    int threads = 0;
    bool speed = true;
    bool raceCheck = true; ///< submission, batch: the race check (race_check.h), where it can run
    bool onlyFigures = false; ///< make-references: only lab_figures.json
    std::string onlyScene;    ///< make-references: only this rubric scene's reference
    bool onlyHidden = false;  ///< make-references: only the hidden scenes' (into the cache)
    bool onlyStale = false;   ///< make-references: only the missing or stale public ones
    // batch
    int jobs = 1;
    int estimateNodes = 10; ///< batch: the Slurm array its time estimate is also given for
    bool force = false;
    bool sceneFiles = false;       ///< rubric: list the files of the public scenes it names
    std::vector<std::string> only; ///< grade only these submission ids (again)
    bool keepStale = false;        ///< keep results graded under another rubric or scenes
    std::string deadline;          ///< ISO 8601; a submission after it is flagged late
    std::string times;             ///< a CSV of id,submitted_at that overrides the times found
    /// batch, merge: earlier terms' token files to compare with (similarity/prior_terms.h);
    /// keep-term: where to write this term's.
    std::string prior;
    std::string term; ///< keep-term: the term's name
    /// submission: when it was handed in (Gradescope's created_at), for the rubric's late policy
    /// against --deadline.
    std::string submittedAt;
    std::string id; ///< submission: the student's id, where the folder's name is not it
    int shard = 0, shards = 1;
    // submission, as batch starts it (and run_autograder)
    std::string kit; ///< compiled lab kit (default: built in the output folder)
    /// References of the hidden scenes, measured once and kept while their files are unchanged
    /// (default: reference-cache/ beside the grader; a batch keeps its own in OUT/.references).
    std::string referenceCache;
    std::string timingLock;
    std::vector<int> timingCpus, workCpus;
};

/// Throws InputError naming the option at fault.
Arguments parseArguments(int argc, char** argv);

/// `grader --help`: the commands and options, with the labs and their files from the lab list.
std::string usage();

} // namespace pathlab::grader
