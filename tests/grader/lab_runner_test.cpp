// Which runs go through the sandbox: any submission with a library for any lab, including one
// that left the first lab out (its renders ran outside the sandbox once, where the submission
// viewer refused to start).
#include "catch.h"

#include "isolation/render_run.h"

using namespace pathlab;
using namespace pathlab::grader;

TEST_CASE("a runner with a library for any lab is sandboxed, and renders each lab with its own",
          "[grader]") {
    LabRunner linkedIn;
    CHECK_FALSE(linkedIn.sandboxed());
    LabRunner uniformOnly;
    uniformOnly.labLibraries[Lab::Uniform] = "labs-uniform.so";
    CHECK(uniformOnly.sandboxed());
    CHECK(uniformOnly.libraryFor(Lab::Uniform) == "labs-uniform.so");
    CHECK(uniformOnly.libraryFor(Lab::Branching).empty());
}
