// The speed check's verdict from timed runs made by hand: a lab undecided after the last pairs
// is given the benefit of the doubt only where the machine's own variation hides its ratio; a
// lab whose runs vary far more than the reference's (slow in some processes, fast in others, at
// random) is judged against the machine's variation and fails.
#include "catch.h"

#include "checks/rubric.h"
#include "checks/speed_check.h"

#include <cmath>

using namespace pathlab;
using namespace pathlab::grader;

namespace {

/// 20 pairs, the cap of the kit's rubric (speed.runs 5): the reference at 1e6 samples per
/// CPU-second with ±3% of the machine's noise, the lab at `rate(i)` in run i.
template <typename Rate> TimedMeasurement pairs(Rate rate) {
    TimedMeasurement t;
    for (int i = 0; i < 20; ++i) {
        const double machine = 1 + 0.03 * std::sin(1.7 * i);
        t.student.push_back(rate(i) * machine);
        t.solution.push_back(1e6 * (1 + 0.03 * std::cos(2.3 * i)));
        t.studentWall.push_back(1), t.solutionWall.push_back(1);
    }
    t.studentSamples = t.solutionSamples = 1e6;
    return t;
}

} // namespace

TEST_CASE("speed: a lab slow at random in some processes gets no benefit of the doubt",
          "[grader]") {
    const Rubric rubric = loadRubric(PATHLAB_GRADER_DIR "/rubric.json");
    // 8 of 20 runs twelve times slower: a geometric mean ratio of about 0.37, whose pairs
    // spread so much that their own interval cannot place it against 0.75.
    const TimedMeasurement t =
        pairs([](int i) { return i % 5 == 1 || i % 5 == 3 ? 1e6 / 12 : 1e6; });
    const SpeedOutcome outcome = judgeTimedRuns(rubric, Lab::Uniform, true, {}, t);
    CHECK_FALSE(outcome.check.passed);
    std::string details;
    for (const std::string& d : outcome.check.details) details += d + "\n";
    CHECK(details.find("vary from run to run") != std::string::npos);
    CHECK(details.find("benefit of the doubt") == std::string::npos);
}

TEST_CASE("speed: a lab at the threshold, its runs as steady as the reference's, keeps the "
          "benefit of the doubt",
          "[grader]") {
    const Rubric rubric = loadRubric(PATHLAB_GRADER_DIR "/rubric.json");
    // 0.745 of the reference with the machine's noise alone: undecided after 20 pairs.
    const TimedMeasurement t = pairs([](int) { return 0.745e6; });
    const SpeedOutcome outcome = judgeTimedRuns(rubric, Lab::Uniform, true, {}, t);
    CHECK(outcome.check.passed);
    std::string details;
    for (const std::string& d : outcome.check.details) details += d + "\n";
    CHECK(details.find("benefit of the doubt is yours") != std::string::npos);
}
