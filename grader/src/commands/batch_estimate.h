#pragma once
/// How long a batch will take, said before its gradings start: per submission on this machine,
/// the submissions to grade here, and a Slurm array of nodes (grader/slurm/), from how long
/// gradings have taken here: the folder's earlier gradings, else the canary's.

#include <optional>
#include <string>

namespace pathlab::grader {

/// The wall-clock seconds one grading takes here, and what that figure is measured from.
struct GradingTime {
    double seconds = 0;
    std::string from; ///< "the median of 12 earlier gradings in OUT", "the canary's ..."
    /// Why the figure may be short ("" if it is a grading like those to come): the canary
    /// grades alone, with no job beside it, and times nothing.
    std::string lowerBoundBecause;
};

/// From OUT's gradings and their earlier attempts (those that rendered, not re-scores; timed or
/// not as this batch times, `speed`), the median; where there is none, the canary's grading
/// (OUT/.canary); none before either exists.
std::optional<GradingTime> measuredGradingTime(const std::string& out, bool speed);

/// What a Slurm array would be given: nodes, and the cores each task asks for (PATHLAB_CPUS).
struct SlurmArray {
    int nodes = 10;
    int cpusPerNode = 4;
};

/// The estimate's lines: `count` submissions graded `jobs` at a time here, and on `array`
/// (each task grading cpus - 1 at a time, as grade-shard.sbatch does, and measuring its own
/// references and canary first), on nodes taken to be as fast as this machine.
std::string batchEstimate(const GradingTime& time, size_t count, int jobs, const SlurmArray& array);

/// The wall-clock seconds `count` gradings of `time` take `jobs` at a time: the class estimate.
double batchSeconds(const GradingTime& time, size_t count, int jobs);

/// "3 min", "1 h 20 min": a duration as an instructor plans with it.
std::string roughDuration(double seconds);

} // namespace pathlab::grader
