#include "checks/race_verdict.h"

namespace pathlab::grader {

void addRaceVerdict(const RaceFinding& finding, CheckResult& correctness) {
    std::vector<std::string>& details = correctness.details;
    if (finding.status == RaceFinding::Status::CouldNotRun) {
        details.push_back("race check not made (not held against the lab): " + finding.problem);
        return;
    }
    if (finding.status == RaceFinding::Status::LabRefused) {
        details.insert(details.begin(),
                       "the lab compiled with ThreadSanitizer does not load, where the same file "
                       "compiled without it does: " +
                           finding.problem +
                           ". Code that differs under the sanitizer is held against the lab, as "
                           "a data race would be");
        correctness.passed = false;
        correctness.score = 0;
        correctness.summary = "its ThreadSanitizer build does not load";
        correctness.diagnosis = "differs under ThreadSanitizer";
        return;
    }
    if (finding.status != RaceFinding::Status::Ran) return;
    if (finding.races.empty()) {
        details.push_back("no data race between render threads (" + finding.how + ")");
        return;
    }
    std::vector<std::string> raceDetails;
    for (const LabRace& race : finding.races) raceDetails.push_back(race.text());
    raceDetails.push_back("found by " + finding.how +
                          "; the image of a lab with a data race is "
                          "undefined behaviour, so correctness fails whatever the image shows");
    // A statistical failure too is kept, after the race, which may be its cause.
    if (!correctness.passed) raceDetails.push_back("also: " + correctness.summary);
    details.insert(details.begin(), raceDetails.begin(), raceDetails.end());
    correctness.passed = false;
    correctness.score = 0;
    correctness.summary = std::string(RaceDiagnosis) + " at " + finding.races.front().line;
    correctness.diagnosis = RaceDiagnosis;
}

} // namespace pathlab::grader
