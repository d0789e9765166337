#pragma once
/// The student's own experiments for the lab report: the plots `make sweep` writes
/// (scripts/sweep.py) into BUILD/sweep/LAB-PARAM/, found where they are, so that `make report`
/// shows them beside the notebook's figures.

#include <string>
#include <vector>

namespace pathlab::grader {

/// One sweep as the report shows it.
struct SweepFigure {
    std::string name; ///< its folder's name: "roulette-continue-prob"
    std::string lab;  ///< the folder's name up to its first '-': "roulette"
    /// As the handouts write it, "continueProb" or "maxDepth", from sweep.csv's first column
    /// ("continue_prob", "max_depth"; another is taken as it is).
    std::string parameter;
    std::string plot;          ///< sweep.png, relative to the report's folder
    std::string table;         ///< sweep.csv, relative to the report's folder
    int values = 0;            ///< rows of sweep.csv
    std::string mostEfficient; ///< the value of the row of highest efficiency, as written; ""
                               ///< when sweep.csv has none
};

/// Each FOLDER/NAME/ that holds a sweep.png and a sweep.csv, by name; none when `folder` does not
/// exist. Paths relative to `reportFolder`, where the Markdown that links them is written.
std::vector<SweepFigure> findSweeps(const std::string& folder, const std::string& reportFolder);

/// The plot `make convergence` writes (scripts/convergence.py), FOLDER/convergence.png with
/// convergence.csv beside it, relative to `reportFolder`; "" when there is none.
std::string findConvergencePlot(const std::string& folder, const std::string& reportFolder);

} // namespace pathlab::grader
