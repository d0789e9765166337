// A batch's time estimate (commands/batch_estimate.h): the figure it rests on, read from the
// gradings a batch folder holds, and the arithmetic of the lines it prints.
#include "catch.h"
#include "test_support.h"

#include "commands/batch_estimate.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

using namespace pathlab::grader;
namespace fs = std::filesystem;

namespace {

void writeResult(const fs::path& folder, double seconds, const std::string& how, bool speed) {
    fs::create_directories(folder);
    std::ofstream(folder / "result.json") << nlohmann::json{
        {"seconds", seconds},
        {"how", how},
        {"graded_under",
         {{"speed_measured", speed}}}}.dump();
}

} // namespace

TEST_CASE("a batch's estimate rests on the median of the folder's gradings, else the canary's",
          "[grader]") {
    const pathlab::test::ScratchFolder scratch("estimate");
    const fs::path out = scratch.path;
    CHECK_FALSE(measuredGradingTime(out.string(), true)); // nothing measured yet

    writeResult(out / ".canary", 20, "graded", false);
    const auto canary = measuredGradingTime(out.string(), true);
    REQUIRE(canary);
    CHECK(canary->seconds == 20);
    CHECK(canary->lowerBoundBecause == "the canary grades alone, with no job beside it, and times "
                                       "nothing");

    writeResult(out / "submissions" / "alice", 30, "graded", true);
    writeResult(out / "submissions" / "bob", 50, "graded", true);
    writeResult(out / "submissions" / "carol", 40, "graded", true);
    writeResult(out / "submissions" / "dave", 0, "re-scored from attempt 1", true);   // took none
    writeResult(out / "submissions" / "dave" / "attempts" / "1", 60, "graded", true); // judged
    writeResult(out / "submissions" / "erin", 500, "graded", false); // not timed: not alike
    const auto earlier = measuredGradingTime(out.string(), true);
    REQUIRE(earlier);
    CHECK(earlier->seconds == 50); // of 30, 40, 50 and dave's attempt, 60
    CHECK(earlier->from ==
          "the median of 4 earlier grading(s) in this folder, earlier attempts included");
    CHECK(earlier->lowerBoundBecause.empty());
}

TEST_CASE("a batch's estimate: per submission, the class here, and a Slurm array", "[grader]") {
    const GradingTime time{30, "the median of 3 earlier grading(s) in this folder", ""};
    const std::string text = batchEstimate(time, 200, 2, SlurmArray{10, 4});
    INFO(text);
    CHECK(text.find("estimate: about 30 s per submission here (the median of 3 earlier "
                    "grading(s) in this folder)\n") == 0);
    // 200 gradings of 30 s, 2 at a time: 3000 s.
    CHECK(text.find("estimate: 200 submission(s) here, 2 at a time: about 50 min\n") !=
          std::string::npos);
    // 20 a node, 3 at a time on 4 cores: 7 rounds of 30 s, after a minute: 270 s.
    CHECK(text.find("on a Slurm array of 10 node(s) of 4 cores (PATHLAB_CPUS), as fast as this "
                    "one: about 5 min (20 a node, 3 at a time") != std::string::npos);
    CHECK(text.find("lower bound") == std::string::npos);
    CHECK(batchEstimate({20, "the canary's grading of the solutions", "the canary grades alone"}, 4,
                        1, {})
              .find("the canary grades alone, so read these as lower bounds") != std::string::npos);
    CHECK(batchSeconds(time, 200, 2) == 3000);
    CHECK(roughDuration(45) == "45 s");
    CHECK(roughDuration(3000) == "50 min");
    CHECK(roughDuration(2 * 3600 + 20 * 60) == "2 h 20 min");
}
