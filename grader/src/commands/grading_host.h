#pragma once
/// What every command that grades in the sandbox needs of the machine: the sandbox itself, and
/// the lab build beside the grader (lab_library_build.json), which the kit is compiled from.

#include "isolation/lab_library.h"

namespace pathlab::grader {

/// The lab build this grader was built with.
LabBuild labBuildOfThisGrader();
/// Throws InputError naming why the sandbox cannot run here, if it cannot.
void requireSandbox();

} // namespace pathlab::grader
