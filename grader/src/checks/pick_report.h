#pragma once
/// For a lab that failed correctness, the pick test of its paths (pathlab/inspect/pick_test.h,
/// `make pick-test`): how often it went on by each component at each material of
/// mixed_surfaces against the probability it divided by. Its words join the feedback ("at Kd
/// 0.8,0.1,0.02 Ks 0.05,0.45,0.3 (19121 visits) you went on by mirror with frequency 0.588 and
/// divided by 0.36"); it scores nothing, so nothing rests on the lab's process saying it.

#include "checks/check_result.h"
#include "checks/grader_setup.h"

namespace pathlab::grader {

/// The scene it replays, in models/: the one whose materials mix two components.
inline constexpr const char* PickTestScene = "mixed_surfaces";

/// Runs the pick test of `lab` in the sandbox and adds its failing lines to `correctness`'s
/// details; adds nothing where it passes, has nothing to test (lab 1, a stub) or cannot run.
void addPickTestReport(const GraderSetup& setup, Lab lab, CheckResult& correctness);

/// The lines of the viewer's --pick-test output that say where the picks and divisions part,
/// printable and at most `most` of them: what addPickTestReport quotes.
std::vector<std::string> pickTestFailures(const std::string& output, size_t most = 4);

} // namespace pathlab::grader
