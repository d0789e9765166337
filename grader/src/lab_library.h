#pragma once
/// Compiling submitted labs, in the sandbox, into a shared library that the submission viewer
/// loads: each lab file on its own (so one that does not compile costs that lab only), then
/// linked with the lab table. The same for the reference solutions, so both are timed alike.

#include "sandbox.h"

#include "pathlab/lab_registry.h"

#include <array>
#include <string>
#include <vector>

namespace pathlab::grader {

/// How this build compiles labs (lab_library_build.json, written by CMake).
struct LabBuild {
    std::string compiler;
    std::vector<std::string> flags;
    std::string include;   ///< framework/include
    std::string labTable;  ///< framework/src/lab_table.cpp
    std::string stubs;     ///< labs/: the stubs stand in for a lab that is missing or broken
    std::string solutions; ///< solutions/
    std::string viewer;    ///< the submission viewer
};

/// Reads the build description beside the grader; throws InputError if it is missing.
LabBuild loadLabBuild(const std::string& path);

/// Compiled once per batch and shared by every submission's link: the lab table, the stubs'
/// objects, and the reference solutions' library.
struct LabKit {
    std::string folder;
    std::string tableObject;
    std::array<std::string, 4> stubObjects; ///< by Lab
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

struct SubmissionLibrary {
    std::string library;                      ///< the shared library, or "" if linking failed
    std::array<LabCompilation, 4> labs;       ///< by Lab
    std::string problem;                      ///< why there is no library
};

/// Compiles the lab files in `sources` (a clean folder holding only allow-listed files) and
/// links them, the stubs standing in for missing or broken ones, into `folder`/labs.so.
SubmissionLibrary buildSubmissionLibrary(const LabBuild& build, const LabKit& kit,
                                         const std::string& sources, const std::string& folder,
                                         const SandboxPolicy& policy);

} // namespace pathlab::grader
