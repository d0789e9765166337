// The diagnoses and hints students read, as the table holds them: each step they name exists in
// the lab file and its handout, each known bug is found from the furnace values it gives, and a
// diagnosis name points at one step.
#include "catch.h"

#include "diagnosis/diagnosis.h"
#include "diagnosis/diagnosis_table.h"

#include "pathlab/support/whole_file.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

using namespace pathlab;
using namespace pathlab::grader;

namespace {

namespace fs = std::filesystem;

const fs::path Kit = fs::path(PATHLAB_GRADER_DIR).parent_path();

/// handouts/0N-*.md, the handout of lab N.
std::string handoutOf(Lab lab) {
    const std::string prefix = "0" + std::to_string(static_cast<int>(lab) + 1) + "-";
    for (const auto& entry : fs::directory_iterator(Kit / "handouts"))
        if (entry.path().filename().string().rfind(prefix, 0) == 0)
            return readFile(entry.path().string());
    FAIL("no handout " << prefix << "*.md in " << (Kit / "handouts").string());
    return "";
}

/// Where a step is named: its marker in the lab file and its section in the handout.
void requireStepExists(LabStep step, Lab lab) {
    const int number = stepNumber(step, lab);
    INFO(labName(lab) << ", step " << static_cast<int>(step));
    REQUIRE(number > 0);
    const std::string name =
        "lab" + std::to_string(static_cast<int>(lab) + 1) + "." + std::to_string(number);
    CHECK(handoutOf(lab).find("### " + name + " ") != std::string::npos);
    // labs/ holds the stubs as shipped in the kit (which has solutions/). In the student release
    // it is the student's work, whose TODO markers go as the steps are written: there the
    // handout alone names the step.
    if (!fs::exists(Kit / "solutions")) return;
    const std::string labFile =
        readFile((Kit / "labs" / (std::string(labName(lab)) + ".cpp")).string());
    CHECK(labFile.find("TODO(" + name + ")") != std::string::npos);
}

bool contains(const std::vector<std::string>& list, const std::string& item) {
    return std::find(list.begin(), list.end(), item) != list.end();
}

} // namespace

TEST_CASE("every step a diagnosis or hint names is in the lab file and its handout", "[grader]") {
    for (Lab lab : AllLabs) {
        for (const KnownBug& bug : knownBugs())
            if (bug.step && (bug.labs & labBit(lab))) {
                requireStepExists(*bug.step, lab);
                CHECK(bugSentence(bug, lab, 3).find(todoName(*bug.step, lab)) != std::string::npos);
            }
        for (const Hint& hint : hints())
            if (hint.step && (hint.labs & labBit(lab))) requireStepExists(*hint.step, lab);
    }
}

TEST_CASE("every known bug is found from the furnace values it gives", "[grader]") {
    // The furnaces a grading renders: the rubric's at maxDepth 3 and continueProb 0.8, and the
    // parameter check's furnace at maxDepth 5 and continueProb 0.5.
    const std::vector<FurnaceModel> furnaces = {{FurnaceWalls::Diffuse, 0.5, 3, 0.8},
                                                {FurnaceWalls::Diffuse, 0.8, 3, 0.8},
                                                {FurnaceWalls::Mirror, 0.5, 3, 0.8},
                                                {FurnaceWalls::Diffuse, 0.5, 5, 0.5}};
    for (Lab lab : AllLabs)
        for (const KnownBug& bug : knownBugs()) {
            if (!(bug.labs & labBit(lab))) continue;
            const int depth = 3; // where a lab renders at a depth of its own
            std::vector<FurnaceObservation> observations;
            for (const FurnaceModel& furnace : furnaces)
                observations.push_back(
                    {furnace, furnaceValueWithBug(lab, furnace, bug, depth), 0.0});
            const std::string sentence = bugSentence(bug, lab, depth);
            INFO(labName(lab) << ": " << sentence);
            CHECK(contains(likelyFurnaceCauses(lab, observations, bug.fits(true)), sentence));
        }
}

TEST_CASE("a diagnosis names one step, and reads as the words before its sentence's colon",
          "[grader]") {
    // A class's summary counts students by diagnosis: two bugs that share one must be fixed in
    // the same step.
    std::map<std::string, std::optional<LabStep>> stepOf;
    for (const KnownBug& bug : knownBugs()) {
        INFO(bug.diagnosis);
        CHECK(std::string(bug.diagnosis).find(':') == std::string::npos);
        const auto [known, added] = stepOf.emplace(bug.diagnosis, bug.step);
        CHECK((added || known->second == bug.step));
    }
    // Each sentence tells its bug apart from the lab's others.
    for (Lab lab : AllLabs) {
        std::set<std::string> sentences;
        for (const KnownBug& bug : knownBugs())
            if (bug.labs & labBit(lab)) CHECK(sentences.insert(bugSentence(bug, lab, 3)).second);
    }
}

TEST_CASE("every lab has a hint on every topic", "[grader]") {
    for (HintTopic topic : {HintTopic::NonfiniteRadiance, HintTopic::DiffuseDirection,
                            HintTopic::Refraction, HintTopic::TooNoisy})
        for (Lab lab : AllLabs) CHECK_FALSE(hintFor(topic, lab).empty());
    // Lab 1 picks no component, so it has no pick to disagree with its division.
    for (Lab lab : AllLabs)
        CHECK(hintFor(HintTopic::PickDivideMismatch, lab).empty() == (lab == Lab::Branching));
}
