#pragma once
/// The window's convergence plot without the drawing: the error of each frame against a
/// reference, kept run by run (a run lasts from one restart of accumulation to the next), and
/// what the plot derives from it: its log-log bounds, the slope −1/2 guide line and the time to
/// unit variance. Kept apart from ImGui so that it can be tested (apps/viewer/convergence_plot.h
/// draws it).

#include <cstddef>
#include <string>
#include <vector>

namespace pathlab {

/// One frame against the reference (pathlab/images/relative_mse.h).
struct ConvergencePoint {
    int spp = 0;
    double seconds = 0; ///< rendering time of all the run's passes so far
    double relMse = 0;
    double relativeRmse = 0;
};

/// What the plot shows up the page, and along it.
enum class ConvergenceMetric { RelativeRmse, RelMse };
enum class ConvergenceAxis { SamplesPerPixel, Seconds };

/// The value of `point` on `axis`, or for `metric`.
double axisValue(const ConvergencePoint& point, ConvergenceAxis axis);
double metricValue(const ConvergencePoint& point, ConvergenceMetric metric);

/// The slope of an unbiased estimator's error on log-log axes: −1/2 for the relative RMSE,
/// −1 for relMSE (its square), whichever the axis (seconds are proportional to spp).
double guideSlope(ConvergenceMetric metric);

/// The time to unit variance, 1 / efficiency: relMSE × seconds, the seconds this estimator
/// would need for a relMSE of 1, and constant along a run as long as the error is variance
/// alone. 0 before the first timed point.
double timeToUnitVariance(const ConvergencePoint& point);

/// One run: what was rendered, in words, and its points, spaced evenly in log spp.
struct ConvergenceRun {
    std::string label;
    std::vector<ConvergencePoint> points;
};

/// A straight line on log-log axes, from (x0, y0) to (x1, y1).
struct LogLine {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

/// Whole decades around some positive values: [10^floor(log10 min), 10^ceil(log10 max)], at
/// least one decade wide; [1, 10] when there are none.
struct LogRange {
    double low = 1, high = 10;
    /// Where `value` falls between low (0) and high (1) on a log scale; clamped to [0, 1].
    double position(double value) const;
};
LogRange decadesAround(const std::vector<double>& values);

class ConvergenceHistory {
public:
    /// Runs kept: the oldest are dropped beyond it.
    static constexpr std::size_t MaxRuns = 8;
    /// A new point is kept when its spp is this factor above the previous kept one's (about 20
    /// a decade); otherwise it replaces the newest, so that the curve ends at the latest frame.
    static constexpr double SppStep = 1.12;

    /// Adds a frame's point. A new run starts when the label changed or the spp did not go up
    /// (a restart: within a run every frame adds samples); a run that ended with fewer than two
    /// points is forgotten, as a camera drag leaves many of them.
    void add(const std::string& label, const ConvergencePoint& point);
    /// Forgets every run.
    void clear() { runs_.clear(); }

    const std::vector<ConvergenceRun>& runs() const { return runs_; }
    /// The run under way, or nullptr before the first point.
    const ConvergenceRun* current() const { return runs_.empty() ? nullptr : &runs_.back(); }

    /// The plot's ranges: decades around every point of every run.
    LogRange axisRange(ConvergenceAxis axis) const;
    LogRange metricRange(ConvergenceMetric metric) const;

    /// The guide line of slope guideSlope(metric) through the current run's newest point,
    /// across the axis' range `x`; none (all zeros) before the first point.
    LogLine guideLine(ConvergenceAxis axis, ConvergenceMetric metric, const LogRange& x) const;

private:
    std::vector<ConvergenceRun> runs_;
};

} // namespace pathlab
