#pragma once
/// The three checks of one lab: correctness, noise, frame rate.

#include "expectation.h"
#include "render_run.h"
#include "rubric.h"

#include <map>
#include <string>
#include <vector>

namespace pathlab::grader {

struct CheckResult {
    std::string name;            ///< "correctness", "noise", "speed"
    double score = 0, maxScore = 0;
    bool passed = false;
    std::string summary;         ///< one line
    std::vector<std::string> details; ///< what to look at, in words
};

struct LabGrade {
    Lab lab;
    std::vector<CheckResult> checks;
    double studentSamplesPerSecond = 0, solutionSamplesPerSecond = 0;
    /// For the HTML report: per scene, the student's mean image, the reference and a heat map.
    struct Pictures {
        std::string scene;
        int width = 0, height = 0;
        std::vector<float> student, reference;
    };
    std::vector<Pictures> pictures;

    double score() const;
    double maxScore() const;
};

/// A scene to grade on: its .ecs path and what it is compared with.
struct GradingScene {
    std::string path;
    SceneReference reference;
    bool isFurnace = false;  ///< the diagnosis knows the furnace's analytic values
    double furnaceAlbedo = 0.5;
};

struct GraderSetup {
    std::string studentViewer;   ///< runs the labs being graded (default implementation)
    std::string solutionViewer;  ///< runs the reference solutions (with --solution)
    Rubric rubric;
    std::vector<GradingScene> scenes;
    std::string scratch;
    uint64_t seedBase = 1;
    int threads = 0;
    bool measureSpeed = true;
};

LabGrade gradeLab(const GraderSetup& setup, Lab lab);

} // namespace pathlab::grader
