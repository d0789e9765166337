#pragma once
/// The race check of grader batch and grader submission: each submitted lab, compiled again with
/// ThreadSanitizer, renders a small image with two threads in the sandbox, in the submission
/// viewer linked with TSan's runtime (viewer-submission-tsan). Only the lab is instrumented, so
/// what TSan reports is a race between two render threads' accesses in the lab's own code: a
/// static or global counter, a shared buffer, which the statistical checks cannot see when it
/// leaves the image as it was (race_report.h reads the reports, race_verdict.h turns them into
/// the correctness verdict).

#include "checks/race_report.h"
#include "isolation/lab_library.h"
#include "isolation/sandbox.h"

#include <cstdint>
#include <string>
#include <vector>

namespace pathlab::grader {

/// How the race check runs on this machine, found by starting the TSan viewer in the sandbox.
struct RaceCheckRuntime {
    /// What starts the viewer inside the sandbox: nothing, or `setarch ARCH -R` on a kernel whose
    /// address randomisation is more than TSan's runtime allows.
    std::vector<std::string> launcher;
    std::string unavailable = "not asked for"; ///< why the check is skipped; "" when it runs

    bool available() const { return unavailable.empty(); }
};

/// Starts the race check's viewer once (about a second); says why not when it cannot run: no
/// TSan in this build (another compiler, a sanitized build), or its runtime does not start here.
RaceCheckRuntime raceCheckRuntime(const LabBuild& build, const SandboxPolicy& policy);

/// What one submission's race checks share.
struct RaceCheckRun {
    LabBuild build;
    LabKit kit;
    RaceCheckRuntime runtime;
    std::string sources;  ///< the submission's lab files, as taken in
    std::string folder;   ///< for the instrumented objects and libraries
    SandboxPolicy policy; ///< for compiling and the render: the grading's own cores
    uint64_t seed = 1;
};

/// Compiles `lab` with TSan, renders the VI2 box at 64x64 with 2 threads, and reads the races
/// reported in the lab's file. TSan sees every access of the lab's code from two threads as a
/// race (TBB's hand-offs are uninstrumented), but only once the second thread has joined the
/// render, which on a busy machine takes up to a second: hence 256 samples per pixel. The two
/// threads share the grading's cores (one core is enough: TSan orders accesses, it does not
/// need them at the same instant).
RaceFinding checkRaces(const RaceCheckRun& run, Lab lab);

} // namespace pathlab::grader
