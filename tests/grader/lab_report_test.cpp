// make report writes lab-report.md again at every run: what the student wrote under "What I
// observed" must survive it, and the prompt alone is not kept as if it were theirs. Its figures
// compare small efficiencies, lab 4's noise at 64 and 256 spp, and the plots of make sweep.
#include "catch.h"
#include "test_support.h"

#include "reports/reports.h"
#include "reports/sweep_figures.h"

#include <filesystem>
#include <fstream>

using namespace pathlab;
using namespace pathlab::grader;

// The rubric's defaults, default-initialized once: GCC 12 at -O3 warns, wrongly, that an
// aggregate-initialized Rubric's strings (Rubric{}) may be used uninitialized, and CI builds
// with warnings as errors.
static const Rubric& defaultRubric() {
    static Rubric rubric;
    return rubric;
}

TEST_CASE("make report keeps what the student wrote under What I observed", "[grader]") {
    const std::string dir = test::temporaryFolder("lab-report");
    const std::string path = dir + "/lab-report.md";
    CHECK(observationsIn(path).empty()); // no report yet

    // First report: the prompt, which is nobody's notes.
    const std::string first =
        labReport(GradeReport{}, defaultRubric(), LabFigures{}, std::nullopt, "");
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
        labReport(GradeReport{}, defaultRubric(), LabFigures{}, std::nullopt, notes);
    std::ofstream(path) << second;
    CHECK(observationsIn(path) == notes);
}

namespace {

/// A report of labs 1 and 4, yours and the reference's figures as given.
GradeReport branchingAndRoulette() {
    GradeReport report;
    for (Lab lab : {Lab::Branching, Lab::Roulette}) {
        LabGrade grade;
        grade.lab = lab;
        report.labs.push_back(grade);
    }
    return report;
}

EstimatorFigures figures(double efficiency, double noise, double noiseLate) {
    EstimatorFigures f;
    f.samplesPerSecond = 1e6, f.framesPerSecond = 4, f.noise = noise, f.efficiency = efficiency;
    f.samplesPerCpuSecond = 5e5;
    f.noiseLate = noiseLate;
    return f;
}

} // namespace

TEST_CASE("the lab report compares small efficiencies and lab 4's noise at 64 and 256 spp",
          "[grader]") {
    LabFigures yours, theirs;
    yours.notebook = {{"branching", figures(2.53, 0.234, 0)},
                      {"roulette", figures(0.0236, 6.14, 10.1)},
                      {"roulette_graded", figures(1.24, 0.382, 0.191)}};
    theirs.notebook = yours.notebook;
    theirs.notebook["roulette"].efficiency = 0.0118;
    const std::string md = labReport(branchingAndRoulette(), defaultRubric(), yours, theirs, "");
    // Efficiency ÷ lab 1's: 0.0236/2.53 and 0.0118/2.53, which two decimals both made 0.01.
    CHECK(md.find("| 0.00933 | 0.00466 |") != std::string::npos);
    CHECK(md.find("## Lab 4: the noise at 64 and at 256 spp") != std::string::npos);
    // q = 0.1: 6.14 then 10.1, a ratio of 1.64 (infinite variance); the graded q halves it.
    CHECK(md.find("| 6.140 | 6.140 | 10.100 | 10.100 | 1.64 | 1.64 |") != std::string::npos);
    CHECK(md.find("| 0.382 | 0.382 | 0.191 | 0.191 | 0.500 | 0.500 |") != std::string::npos);
    // Without a sweep, the report says how to make one.
    CHECK(md.find("No sweep run yet: `make sweep LAB=roulette`") != std::string::npos);

    // A reference stored before lab_figures.json had the late noise: says how to get it.
    theirs.notebook["roulette"].noiseLate = 0;
    const std::string older = labReport(branchingAndRoulette(), defaultRubric(), yours, theirs, "");
    CHECK(older.find("not stored (grader make-references --only-figures)") != std::string::npos);
}

TEST_CASE("the lab report's ratios are of CPU-time figures, and it says when the machine was busy",
          "[grader]") {
    LabFigures yours;
    yours.notebook = {{"branching", figures(2.53, 0.234, 0)},
                      {"roulette", figures(0.0236, 6.14, 10.1)},
                      {"roulette_graded", figures(1.24, 0.382, 0.191)}};
    // Lab 4 at q = 0.1: four times lab 1's samples per CPU-second, a wall-clock frame rate
    // that a busy machine held to lab 1's.
    yours.notebook["roulette"].samplesPerCpuSecond = 2e6;
    yours.notebook["roulette"].notes = {"the machine was busy: the render threads had 31%"};
    const std::string md = labReport(branchingAndRoulette(), defaultRubric(), yours, yours, "");
    CHECK(md.find("| samples per CPU-second ÷ lab 1's: yours | reference |") != std::string::npos);
    CHECK(md.find("| roulette, continueProb 0.1 (lab 4's default) | 4.00 | 4.00 |") !=
          std::string::npos);
    CHECK(md.find("Notes on your renders:\n\n- roulette, continueProb 0.1 (lab 4's default): the "
                  "machine was busy: the render threads had 31%") != std::string::npos);
}

TEST_CASE("the lab report names a speed at risk and its cause", "[grader]") {
    GradeReport report = branchingAndRoulette();
    CheckResult speed;
    speed.kind = CheckKind::Speed;
    speed.maxScore = 2;
    speed.gradedHere = false;
    speed.atRisk = true;
    speed.summary = "at risk: your lab would likely lose these points";
    speed.details = {"traces 1.7× the bounce rays of the lab's estimator: a black component "
                     "traced?"};
    report.labs[0].checks = {CheckResult{}, CheckResult{}, speed};
    const std::string md = labReport(report, defaultRubric(), LabFigures{}, std::nullopt, "");
    CHECK(md.find("(+2 speed: graded by the instructor; **at risk**)") != std::string::npos);
    CHECK(md.find("graded by the instructor: **at risk** (below)") != std::string::npos);
    CHECK(md.find("**branching, speed:** at risk: your lab would likely lose these points\n- "
                  "traces 1.7× the bounce rays") != std::string::npos);
    CHECK(report.pointsAtRisk() == 2);
    CHECK(terminalReport(report, false)
              .find("(+2 speed: graded by the instructor; 2 of them at "
                    "risk)") != std::string::npos);
}

TEST_CASE("the lab report shows the plots make sweep wrote, linked from the report's folder",
          "[grader]") {
    const std::string dir = test::temporaryFolder("lab-report-sweeps");
    const std::string sweeps = dir + "/build/sweep";
    std::filesystem::create_directories(sweeps + "/roulette-continue-prob");
    std::filesystem::create_directories(sweeps + "/not-a-sweep"); // no plot: left out
    std::ofstream(sweeps + "/roulette-continue-prob/sweep.png") << "png";
    std::ofstream(sweeps + "/roulette-continue-prob/sweep.csv")
        << "continue_prob,samples_per_second,frame_rate,rays_per_sample,noise_per_sample,"
           "efficiency,noise,spp,seconds,width,height\n"
           "0.1,1,1,1,1,0.0104,1,64,1,256,256\n0.8,1,1,1,1,1.46,1,64,1,256,256\n"
           "0.9,1,1,1,1,1.40,1,64,1,256,256\n";
    const std::vector<SweepFigure> found = findSweeps(sweeps, dir);
    REQUIRE(found.size() == 1);
    CHECK(found[0].plot == "build/sweep/roulette-continue-prob/sweep.png");
    CHECK(found[0].values == 3);
    CHECK(found[0].mostEfficient == "0.8");
    CHECK(findSweeps(dir + "/nowhere", dir).empty());

    const std::string md =
        labReport(branchingAndRoulette(), defaultRubric(), LabFigures{}, std::nullopt, "", found);
    CHECK(md.find("### roulette: continueProb\n") != std::string::npos);
    CHECK(md.find("![roulette: samples per CPU-second, noise and efficiency against "
                  "continueProb](build/sweep/roulette-continue-prob/sweep.png)") !=
          std::string::npos);
    CHECK(md.find("3 values, numbers in [build/sweep/roulette-continue-prob/sweep.csv]") !=
          std::string::npos);
    CHECK(md.find("the most efficient: continueProb 0.8") != std::string::npos);
}

TEST_CASE("the lab report shows make convergence's plot when there is one", "[grader]") {
    const std::string dir = test::temporaryFolder("lab-report-convergence");
    const std::string folder = dir + "/build/convergence";
    CHECK(findConvergencePlot(folder, dir).empty());
    const std::string without =
        labReport(branchingAndRoulette(), defaultRubric(), LabFigures{}, std::nullopt, "", {});
    CHECK(without.find("make convergence") == std::string::npos);

    std::filesystem::create_directories(folder);
    std::ofstream(folder + "/convergence.png") << "png";
    CHECK(findConvergencePlot(folder, dir).empty()); // no convergence.csv beside it
    std::ofstream(folder + "/convergence.csv") << "lab,label\n";
    const std::string plot = findConvergencePlot(folder, dir);
    CHECK(plot == "build/convergence/convergence.png");
    const std::string md = labReport(branchingAndRoulette(), defaultRubric(), LabFigures{},
                                     std::nullopt, "", {}, plot);
    CHECK(md.find("No sweep run yet") != std::string::npos);
    CHECK(md.find("### Error against render time\n\n![the relative RMSE of my four labs against "
                  "render time](build/convergence/convergence.png)") != std::string::npos);
}
