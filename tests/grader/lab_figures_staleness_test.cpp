// Which part of the stored lab_figures.json a rubric still fits (reports/lab_figures.h): what
// grader make-references --only-stale, and so make student-release RUBRIC=..., measures again.
#include "catch.h"

#include "checks/rubric.h"
#include "reports/lab_figures.h"

using namespace pathlab;
using namespace pathlab::grader;

namespace {

const std::string KitFigures = PATHLAB_GRADER_DIR "/references/lab_figures.json";

} // namespace

TEST_CASE("the stored figures' timed runs and notebook are stale apart", "[grader]") {
    Rubric rubric = loadRubric(PATHLAB_GRADER_DIR "/rubric.json");
    FiguresStaleness stale = labFiguresStaleness(KitFigures, rubric);
    CHECK(stale.timedRuns.empty()); // the kit's figures fit the kit's rubric
    CHECK(stale.notebook.empty());

    Rubric smaller = rubric; // other timed runs, the same noise scene: the notebook still fits
    smaller.width = smaller.height = 32;
    stale = labFiguresStaleness(KitFigures, smaller);
    CHECK(stale.timedRuns.find("timed runs are not the rubric's") != std::string::npos);
    CHECK(stale.notebook.empty());

    Rubric deeper = rubric; // the notebook renders at the rubric's max depth
    deeper.maxDepth += 1;
    CHECK(labFiguresStaleness(KitFigures, deeper).notebook.find("max depth") != std::string::npos);
    Rubric otherNoise = rubric;
    otherNoise.noiseScene = "furnace";
    CHECK(!labFiguresStaleness(KitFigures, otherNoise).notebook.empty());

    stale = labFiguresStaleness("/nonexistent/lab_figures.json", rubric);
    CHECK(!stale.timedRuns.empty());
    CHECK(!stale.notebook.empty());
}
