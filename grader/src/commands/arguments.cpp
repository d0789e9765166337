#include "commands/arguments.h"

#include "checks/grading_scenes.h"

#include "pathlab/support/input_error.h"
#include "pathlab/support/parse_number.h"
#include "pathlab/support/this_process.h"

#include <filesystem>
#include <functional>
#include <map>

namespace pathlab::grader {

namespace {

/// The usage text; @LAB_FILES@ and @LAB_NAMES@ stand for the lab list's files and names.
const char* const usageTemplate =
    R"(usage: grader [options]                       grade the labs of this build
       grader rubric                          print the rubric in words: points, thresholds, scenes
the instructor's (they need the reference solutions, or a batch's output):
       grader make-references [options]       measure grader/references/ from the solutions
       grader submission PATH --out DIR       grade one submission, in the sandbox
       grader batch SUBMISSIONS --out DIR     grade every submission in a folder, in the sandbox
       grader merge DIR... --out DIR          merge the gradebooks of batch shards
       grader make-variants DIR               write the rubric's variants of the public scenes
                                              into DIR, as hidden scenes (--variant-seed N)
       grader keep-term OUT --term NAME --prior DIR
                                              keep a graded class's lab files as tokens (no
                                              code) in DIR/NAME.json, for later terms' --prior
       grader student-variants ID... --out DIR
                                              write each student's own variant folder, DIR/ID/
                                              (the rubric's variants.per_student), to send them

A submission is a folder, a .zip, a .tar.gz or a git repository holding the lab files
(@LAB_FILES@); only those are taken.

options
  --lab NAME          grade one lab: @LAB_NAMES@
  --viewer PATH       the viewer whose labs are graded (default: the one beside grader)
  --solution-viewer PATH
                      the viewer whose --solution is the reference (default: --viewer)
  --scenes DIR        the hidden scenes: also grade on every .ecs in DIR, references measured
                      from the solutions (default: grader/hidden_scenes/ when it holds any;
                      --scenes none grades on the public scenes only)
  --reference-cache DIR
                      where the hidden scenes' references, measured from the solutions, are
                      kept (default: reference-cache/ beside the grader; a batch keeps its own
                      in OUT/.references)
  --reveal-hidden     feedback names the hidden scenes and shows their images and tiles
                      (by default it says only pass or fail and a likely cause)
  --variant DIR       also grade on your own variant's scenes, from the folder your instructor
                      sent you (when their rubric grades each student on a variant)
  --rubric FILE       points and thresholds (default: grader/rubric.json)
  --scene-files       rubric: list the files of the public scenes the rubric names, one a line
                      (what make student-release RUBRIC=FILE packs)
  --references DIR    stored references (default: grader/references)
  --seed N            seed base (default 1); a fail is re-checked on fresh seeds anyway
  --threads N         threads per render (default: all cores)
  --no-speed          skip the speed check (its points are left out of the total)
  --json FILE --junit FILE --gradescope FILE --prairielearn FILE --html DIR
                      reports (the terminal table is always printed)
  --report FILE.md    a lab report: your notebook's figures (frame rate, noise, efficiency) and
                      the ratios between labs, beside the reference solutions'
  --sweeps DIR        the plots of make sweep the lab report shows (default: sweep/ beside
                      the grader, where make sweep writes them)

make-references
  --only-figures      measure only lab_figures.json: the reference solutions' notebook figures
                      and timed runs on this machine (about a minute)
  --only-scene NAME   measure only the reference of NAME, a scene of the rubric (a scene just
                      added to it), and not lab_figures.json
  --only-hidden       measure only the hidden scenes' references, into the reference cache
                      (Gradescope's setup.sh does this once, so no submission waits for it)
  --only-stale        measure only the public scenes whose reference in --references is
                      missing or no longer fits the rubric, and lab_figures.json only if it
                      was measured for other timed runs (make student-release RUBRIC=FILE
                      does this for the instructor's rubric)

batch
  --out DIR           gradebook.csv, summary.html, batch.log and submissions/ID/ (feedback)
  --jobs N            submissions graded at once (default 1)
  --estimate-nodes N  the Slurm array the time estimate printed before the gradings is also
                      given for: N nodes of PATHLAB_CPUS cores (default 10 nodes of 4)
  --force             grade again what is already graded (default: a restart skips it)
  --only ID[,ID...]   grade only these submissions (again); the gradebook keeps the others
  --keep-stale        keep results graded under another rubric or other scenes (default: grade
                      them again); the gradebook marks them stale
  --deadline TIME     flag submissions made after TIME (2026-12-01T23:59, local time, or with
                      Z or +01:00) as late in the gradebook; the labs' own deadlines, where
                      the rubric's late policy gives them, go first
  --id ID             submission: the student's id, where the submission's folder is not named
                      by it (per-student variants and the late policy's extensions go by it)
  --submitted-at TIME submission: when it was handed in; with --deadline, the rubric's late
                      policy lowers its Gradescope and PrairieLearn scores (run_autograder
                      passes Gradescope's created_at and due date)
  --times FILE.csv    submission times (id,submitted_at, or id,lab,submitted_at for one lab)
                      from your LMS, in place of those found (a git repository's last commit,
                      else the submission's file time)
  --prior DIR         also compare the class's files with the earlier terms kept in DIR
                      (grader keep-term), not those among themselves; merge takes it too
  --shard K/N         grade only every N-th submission, starting at the K-th (0-based)
  --no-race-check     skip the race check (each lab compiled with ThreadSanitizer and rendered
                      with 2 threads: a data race in its own code fails correctness)
  --variant-seed N    where no hidden scenes are kept (and not --scenes none), the batch grades
                      on the rubric's hidden_scenes.variants variants of the public scenes, made
                      from this seed (default: the one kept in OUT/.variants/seed, else a new
                      one); every shard of one class must be given the same
)";

void replaceAll(std::string& text, const std::string& placeholder, const std::string& value) {
    for (size_t at = text.find(placeholder); at != std::string::npos;
         at = text.find(placeholder, at + value.size()))
        text.replace(at, placeholder.size(), value);
}

} // namespace

std::string usage() {
    std::string text = usageTemplate, files;
    for (Lab lab : AllLabs) files += (files.empty() ? "" : ", ") + labFileName(lab);
    replaceAll(text, "@LAB_FILES@", files);
    replaceAll(text, "@LAB_NAMES@", labNames(" | "));
    return text;
}

namespace {

std::vector<int> cpuList(const std::string& option, const std::string& text) {
    std::vector<int> cpus;
    for (std::string_view piece : splitAt(text, ',')) {
        try {
            cpus.push_back(std::stoi(std::string(piece)));
        } catch (const std::exception&) {
            throw InputError("option " + option + " expects core numbers like 0 or 1,2, got '" +
                             text + "'");
        }
    }
    return cpus;
}

long long number(const std::string& option, const std::string& text, long long low) {
    try {
        size_t used = 0;
        const long long value = std::stoll(text, &used);
        if (used == text.size() && value >= low) return value;
    } catch (const std::exception&) {
    }
    throw InputError("option " + option + " expects a whole number of at least " +
                     std::to_string(low) + ", got '" + text + "'");
}

bool isExecutableFile(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code error;
    const fs::file_status status = fs::status(path, error);
    return !error && fs::is_regular_file(status) &&
           (status.permissions() & fs::perms::owner_exec) != fs::perms::none;
}

/// The command, when argv[1] names one; returns the index of the first option.
int readCommand(int argc, char** argv, Arguments& a) {
    if (argc <= 1) return 1;
    int first = 1;
    const std::string command = argv[1];
    for (const char* known : {"make-references", "submission", "batch", "merge", "rubric",
                              "make-variants", "student-variants", "keep-term"})
        if (command == known) a.command = command, first = 2;
    // The instructor's commands compile or run the reference solutions.
    if (!PATHLAB_HAS_SOLUTIONS && first == 2 && a.command != "merge" && a.command != "rubric" &&
        a.command != "make-variants" && a.command != "keep-term")
        throw InputError("grader " + a.command +
                         " is the instructor's: it needs the reference "
                         "solutions (solutions/), which the student release does not have; "
                         "`make grade` grades your labs");
    return first;
}

/// The options that set a flag.
const std::map<std::string, bool Arguments::*>& flagOptions() {
    static const std::map<std::string, bool Arguments::*> flags = {
        {"--reveal-hidden", &Arguments::revealHidden}, {"--only-hidden", &Arguments::onlyHidden},
        {"--keep-stale", &Arguments::keepStale},       {"--only-figures", &Arguments::onlyFigures},
        {"--only-stale", &Arguments::onlyStale},       {"--force", &Arguments::force},
        {"--scene-files", &Arguments::sceneFiles},
    };
    return flags;
}

/// The options that take a text as it is (a path, a time, a name).
const std::map<std::string, std::string Arguments::*>& textOptions() {
    static const std::map<std::string, std::string Arguments::*> texts = {
        {"--viewer", &Arguments::viewer},
        {"--solution-viewer", &Arguments::solutionViewer},
        {"--deadline", &Arguments::deadline},
        {"--submitted-at", &Arguments::submittedAt},
        {"--id", &Arguments::id},
        {"--prior", &Arguments::prior},
        {"--term", &Arguments::term},
        {"--times", &Arguments::times},
        {"--rubric", &Arguments::rubric},
        {"--references", &Arguments::references},
        {"--only-scene", &Arguments::onlyScene},
        {"--json", &Arguments::json},
        {"--junit", &Arguments::junit},
        {"--gradescope", &Arguments::gradescope},
        {"--prairielearn", &Arguments::prairielearn},
        {"--html", &Arguments::html},
        {"--report", &Arguments::report},
        {"--sweeps", &Arguments::sweeps},
        {"--out", &Arguments::out},
        {"--kit", &Arguments::kit},
        {"--reference-cache", &Arguments::referenceCache},
        {"--timing-lock", &Arguments::timingLock},
        {"--variant", &Arguments::variant},
    };
    return texts;
}

using Checked = std::function<void(const std::string& option, const std::string& value)>;

/// The options whose value is checked before it is taken into `a`; --scenes also sets
/// `scenesGiven`.
std::map<std::string, Checked> checkedOptions(Arguments& a, bool& scenesGiven) {
    return {
        {"--lab",
         [&](const std::string&, const std::string& name) {
             const auto lab = labFromName(name);
             if (!lab)
                 throw InputError("option --lab expects one of " + labNames(", ") + ", got '" +
                                  name + "'");
             a.labs = {*lab};
         }},
        {"--scenes",
         [&](const std::string&, const std::string& folder) {
             a.scenesDir = folder;
             scenesGiven = true;
         }},
        {"--only",
         [&](const std::string&, const std::string& ids) {
             if (ids.find_first_not_of(", ") == std::string::npos)
                 throw InputError("option --only expects submission ids, like alice or alice,bob");
             for (std::string_view id : splitAt(ids, ','))
                 if (!id.empty()) a.only.emplace_back(id);
         }},
        {"--seed", [&](const std::string& o,
                       const std::string& v) { a.seed = static_cast<uint64_t>(number(o, v, 0)); }},
        {"--variant-seed",
         [&](const std::string& o, const std::string& v) {
             a.variantSeed = static_cast<uint64_t>(number(o, v, 1));
         }},
        {"--threads", [&](const std::string& o,
                          const std::string& v) { a.threads = static_cast<int>(number(o, v, 0)); }},
        {"--jobs", [&](const std::string& o,
                       const std::string& v) { a.jobs = static_cast<int>(number(o, v, 1)); }},
        {"--estimate-nodes",
         [&](const std::string& o, const std::string& v) {
             a.estimateNodes = static_cast<int>(number(o, v, 1));
         }},
        {"--shard",
         [&](const std::string& o, const std::string& text) {
             const size_t slash = text.find('/');
             if (slash == std::string::npos)
                 throw InputError("option --shard expects K/N, got '" + text + "'");
             a.shard = static_cast<int>(number(o, text.substr(0, slash), 0));
             a.shards = static_cast<int>(number(o, text.substr(slash + 1), 1));
             if (a.shard >= a.shards)
                 throw InputError("option --shard: K must be below N in K/N, got '" + text + "'");
         }},
        {"--timing-cpus",
         [&](const std::string& o, const std::string& v) { a.timingCpus = cpuList(o, v); }},
        {"--work-cpus",
         [&](const std::string& o, const std::string& v) { a.workCpus = cpuList(o, v); }},
    };
}

/// Reads the options and inputs from argv[first] on into `a`, by what each option takes: a
/// flag, a text, or a value to check.
void readOptions(int argc, char** argv, int first, Arguments& a, bool& scenesGiven) {
    const std::map<std::string, Checked> checked = checkedOptions(a, scenesGiven);
    for (int i = first; i < argc; ++i) {
        const std::string arg = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw InputError("option " + arg + " needs a value");
            return argv[++i];
        };
        if (const auto flag = flagOptions().find(arg); flag != flagOptions().end())
            a.*(flag->second) = true;
        else if (const auto text = textOptions().find(arg); text != textOptions().end())
            a.*(text->second) = value();
        else if (const auto check = checked.find(arg); check != checked.end())
            check->second(arg, value());
        else if (arg == "--no-speed")
            a.speed = false;
        else if (arg == "--no-race-check")
            a.raceCheck = false;
        else if (arg == "--help" || arg == "-h")
            a.command = "help";
        else if (!arg.empty() && arg[0] == '-')
            throw InputError("unknown option '" + arg + "' (grader --help lists the options)");
        else if (a.command == "submission" || a.command == "batch" || a.command == "merge" ||
                 a.command == "make-variants" || a.command == "student-variants" ||
                 a.command == "keep-term")
            a.inputs.push_back(arg);
        else
            throw InputError("unexpected argument '" + arg +
                             "' (grader --help lists the commands)");
    }
}

/// The hidden scenes' folder: the default one unless --scenes names another or none; a folder
/// named is checked now, before any grading starts.
void settleHiddenScenes(Arguments& a, bool scenesGiven) {
    if (!scenesGiven) {
        a.scenesDir = defaultHiddenScenesFolder();
    } else if (a.scenesDir == "none") {
        a.scenesDir.clear();
        a.scenesNone = true;
    } else if (!PATHLAB_HAS_SOLUTIONS)
        throw InputError(
            "option --scenes: a hidden scene's reference is measured from the reference "
            "solutions, which the student release does not have");
    else
        hiddenScenePaths(a.scenesDir); // says now if the folder is wrong
}

/// Throws InputError when the command lacks what it needs (inputs, --out) or was given an
/// option that is not its own.
void requireWhatTheCommandNeeds(const Arguments& a) {
    if (!a.only.empty() && a.command != "batch")
        throw InputError("option --only is for grader batch");
    if (a.command == "submission" && a.inputs.size() != 1)
        throw InputError(
            "grader submission expects one submission (a folder, .zip, .tar.gz or git repository)");
    if ((a.command == "batch" || a.command == "merge") && a.inputs.empty())
        throw InputError("grader " + a.command + " expects at least one folder");
    if ((a.command == "submission" || a.command == "batch" || a.command == "merge") &&
        a.out.empty())
        throw InputError("grader " + a.command + " needs --out DIR");
    if (a.command == "keep-term" && (a.inputs.size() != 1 || a.term.empty() || a.prior.empty()))
        throw InputError("grader keep-term expects one batch output folder, --term NAME and "
                         "--prior DIR");
    if (!a.prior.empty() && a.command != "batch" && a.command != "merge" &&
        a.command != "keep-term")
        throw InputError("option --prior is for grader batch, merge and keep-term");
    // Said now, not after a batch's gradings, when the similarity report reads it.
    if (!a.prior.empty() && a.command != "keep-term" && !std::filesystem::is_directory(a.prior))
        throw InputError("option --prior: '" + a.prior +
                         "' is not a folder (grader keep-term writes one)");
    if (!a.id.empty() && a.command != "submission")
        throw InputError("option --id is for grader submission");
    if (!a.submittedAt.empty() && (a.command != "submission" || a.deadline.empty()))
        throw InputError("option --submitted-at is for grader submission, with --deadline");
    if (a.command == "student-variants" && (a.inputs.empty() || a.out.empty()))
        throw InputError("grader student-variants expects the students' ids and --out DIR");
    if (!a.variant.empty() && a.command != "grade")
        throw InputError("option --variant is for grading your labs (grader, make grade)");
    if (a.command == "make-variants" && a.inputs.size() != 1)
        throw InputError("grader make-variants expects one folder to write the variants into");
    if (a.variantSeed != 0 && a.command != "batch" && a.command != "make-variants")
        throw InputError("option --variant-seed is for grader batch and grader make-variants");
}

/// The viewers: the one beside the grader unless named, checked to be programs before any
/// render would fail on them.
void settleViewers(Arguments& a) {
    if (a.viewer.empty()) a.viewer = (thisProgram().parent_path() / "viewer").string();
    if (a.solutionViewer.empty()) a.solutionViewer = a.viewer;
    for (const std::string& v : {a.viewer, a.solutionViewer})
        if (!isExecutableFile(v)) throw InputError("viewer '" + v + "' is not an executable file");
}

} // namespace

Arguments parseArguments(int argc, char** argv) {
    Arguments a;
    a.rubric = std::string(PATHLAB_GRADER_DIR) + "/rubric.json";
    a.references = std::string(PATHLAB_GRADER_DIR) + "/references";
    const int first = readCommand(argc, argv, a);
    bool scenesGiven = false;
    readOptions(argc, argv, first, a, scenesGiven);
    for (int i = first; i < argc; ++i) {
        a.rubricGiven = a.rubricGiven || std::string(argv[i]).rfind("--rubric", 0) == 0;
        a.referencesGiven = a.referencesGiven || std::string(argv[i]).rfind("--references", 0) == 0;
    }
    if (a.command == "help") return a;
    settleHiddenScenes(a, scenesGiven);
    if (a.sceneFiles && a.command != "rubric")
        throw InputError("option --scene-files is for grader rubric");
    if (a.command == "rubric") return a;
    if (a.referenceCache.empty())
        a.referenceCache = (thisProgram().parent_path() / "reference-cache").string();
    if (a.sweeps.empty()) a.sweeps = (thisProgram().parent_path() / "sweep").string();
    requireWhatTheCommandNeeds(a);
    settleViewers(a);
    return a;
}

} // namespace pathlab::grader
