// make report writes lab-report.md again at every run: what the student wrote under "What I
// observed" must survive it, and the prompt alone is not kept as if it were theirs.
#include "catch.h"
#include "test_support.h"

#include "reports/reports.h"

#include <fstream>

using namespace pathlab;
using namespace pathlab::grader;

TEST_CASE("make report keeps what the student wrote under What I observed", "[grader]") {
    const std::string dir = test::temporaryFolder("lab-report");
    const std::string path = dir + "/lab-report.md";
    CHECK(observationsIn(path).empty()); // no report yet

    // First report: the prompt, which is nobody's notes.
    const std::string first = labReport(GradeReport{}, Rubric{}, LabFigures{}, std::nullopt, "");
    std::ofstream(path) << first;
    CHECK(first.find("## What I observed\n\n<!--") != std::string::npos);
    CHECK(observationsIn(path).empty());

    // The student writes below the heading; the next report carries it over, word for word.
    std::ofstream(path) << first << "Lab 2 is noisier: it traces a bounce one time in three.\n";
    const std::string notes = observationsIn(path);
    CHECK(notes.find("<!--") == 0); // the prompt they left stays with their text
    CHECK(notes.find("Lab 2 is noisier: it traces a bounce one time in three.\n") !=
          std::string::npos);
    const std::string second =
        labReport(GradeReport{}, Rubric{}, LabFigures{}, std::nullopt, notes);
    std::ofstream(path) << second;
    CHECK(observationsIn(path) == notes);
}
