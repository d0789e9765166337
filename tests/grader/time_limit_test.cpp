// Each render's time limit grows with how much slower the machine runs now than when the
// references were made, within bounds, and the report says so in numbers.
#include "catch.h"

#include "isolation/time_limit.h"

using namespace pathlab::grader;

TEST_CASE("The time limit scales with the start-up's slow-down, from 1 to MaxSlowness",
          "[time_limit]") {
    CHECK(scaledTimeLimit(30, 0.4, 0.2) == Approx(60));                // twice as slow
    CHECK(scaledTimeLimit(30, 0.1, 0.2) == Approx(30));                // faster: never shorter
    CHECK(scaledTimeLimit(30, 50.0, 0.2) == Approx(30 * MaxSlowness)); // at most
}

TEST_CASE("Without both start-ups the rubric's limit holds", "[time_limit]") {
    CHECK(scaledTimeLimit(30, 0.4, 0) == Approx(30)); // references made before start-ups were kept
    CHECK(scaledTimeLimit(30, 0, 0.2) == Approx(30)); // no start-up render ran
}

TEST_CASE("The note gives the slow-down and the limit", "[time_limit]") {
    const std::string note = timeLimitNote(30, 69);
    CHECK(note.find("2.3 times slower") != std::string::npos);
    CHECK(note.find("may take 69 s") != std::string::npos);
}
