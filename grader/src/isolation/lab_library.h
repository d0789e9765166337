#pragma once
/// Compiling submitted labs, in the sandbox, into shared libraries that the submission viewer
/// loads: each lab file compiled and linked on its own (so one that does not compile, or hangs
/// while loading, costs that lab only), with the lab table. The reference solutions are built
/// the same way, into one library, so both are timed alike.

#include "common/by_lab.h"
#include "isolation/sandbox.h"

#include "pathlab/render/lab_registry.h"

#include <string>
#include <vector>

namespace pathlab::grader {

/// How this build compiles labs (lab_library_build.json, written by CMake).
struct LabBuild {
    std::string compiler;
    std::vector<std::string> flags;
    std::string include; ///< framework/include: the student API and what it includes
    /// The build's generated/include: the headers of the API CMake writes (pathlab/lab_list.h).
    std::string generatedInclude;
    std::string runnerInclude; ///< runner/include: the lab tables lab_table.cpp defines
    std::string labTable;      ///< runner/src/lab_table.cpp
    std::string stubs;         ///< labs/: the stubs stand in for a lab that is missing or broken
    std::string solutions;     ///< solutions/
    std::string viewer;        ///< the submission viewer
    /// The race check's (race_check.h): the submission viewer linked with ThreadSanitizer ("" in
    /// a build without it), and the flags a lab is compiled and linked with for it.
    std::string raceCheckViewer;
    std::vector<std::string> raceCheckFlags;
};

/// Reads the build description beside the grader; throws InputError if it is missing.
LabBuild loadLabBuild(const std::string& path);

/// Compiled once per batch and shared by every submission's link: the lab table, the stubs'
/// objects, and the reference solutions' library.
struct LabKit {
    std::string folder;
    std::string tableObject;
    ByLab<std::string> stubObjects;
    std::string solutionsLibrary;
};

/// Builds the kit into `folder`, or reuses the one there if it was built from the same compiler,
/// flags and sources; throws std::runtime_error if the trusted sources do not compile.
LabKit buildLabKit(const LabBuild& build, const std::string& folder, const SandboxPolicy& policy);
/// The kit buildLabKit made in `folder` before; throws InputError if a part is missing.
LabKit existingLabKit(const std::string& folder);

/// What became of one submitted lab file.
struct LabCompilation {
    enum class Status { Compiled, NotSubmitted, Failed } status = Status::NotSubmitted;
    std::string messages; ///< the compiler's first lines, when it failed
};

/// A submission's labs, each in a library of its own: lab L's object with the stubs standing in
/// for the other three, so that loading one lab never runs another lab's code (a static
/// initializer that hangs costs its own lab only).
struct SubmissionLibrary {
    ByLab<LabCompilation> labs;
    ByLab<std::string> library; ///< "" unless the lab compiled and linked
    ByLab<std::string> problem; ///< why a compiled lab did not link

    bool linked(Lab lab) const { return !library[lab].empty(); }
};

/// Compiles the lab files in `sources` (a clean folder holding only allow-listed files) and
/// links each that compiles into `folder`/labs-LAB.so.
SubmissionLibrary buildSubmissionLibrary(const LabBuild& build, const LabKit& kit,
                                         const std::string& sources, const std::string& folder,
                                         const SandboxPolicy& policy);

/// Compiles lab `lab`'s file in `sources` again, instrumented with `build.raceCheckFlags`, and
/// links it as buildSubmissionLibrary does into `folder`/labs-LAB-tsan.so, whose path it puts in
/// `library`. Returns why it could not, or "".
std::string buildRaceCheckLibrary(const LabBuild& build, const LabKit& kit, Lab lab,
                                  const std::string& sources, const std::string& folder,
                                  const SandboxPolicy& policy, std::string& library);

} // namespace pathlab::grader
