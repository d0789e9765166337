#include "runner/convergence_history.h"

#include <algorithm>
#include <cmath>

namespace pathlab {

double axisValue(const ConvergencePoint& point, ConvergenceAxis axis) {
    return axis == ConvergenceAxis::Seconds ? point.seconds : static_cast<double>(point.spp);
}

double metricValue(const ConvergencePoint& point, ConvergenceMetric metric) {
    return metric == ConvergenceMetric::RelMse ? point.relMse : point.relativeRmse;
}

double guideSlope(ConvergenceMetric metric) {
    return metric == ConvergenceMetric::RelMse ? -1.0 : -0.5;
}

double timeToUnitVariance(const ConvergencePoint& point) {
    return point.seconds > 0 ? point.relMse * point.seconds : 0.0;
}

double LogRange::position(double value) const {
    if (!(value > 0)) return 0;
    const double t = std::log(value / low) / std::log(high / low);
    return std::clamp(t, 0.0, 1.0);
}

LogRange decadesAround(const std::vector<double>& values) {
    double smallest = 0, largest = 0;
    for (double v : values) {
        // Zero (a render equal to its reference) and non-finite values have no place on a log
        // scale: they are left out rather than stretching the axis.
        if (!(v > 0) || !std::isfinite(v)) continue;
        smallest = smallest > 0 ? std::min(smallest, v) : v;
        largest = std::max(largest, v);
    }
    if (!(smallest > 0)) return LogRange{};
    LogRange range;
    range.low = std::pow(10.0, std::floor(std::log10(smallest)));
    range.high = std::pow(10.0, std::ceil(std::log10(largest)));
    if (range.high <= range.low) range.high = range.low * 10;
    return range;
}

void ConvergenceHistory::add(const std::string& label, const ConvergencePoint& point) {
    const bool restarted =
        runs_.empty() || runs_.back().label != label || point.spp <= runs_.back().points.back().spp;
    if (restarted) {
        if (!runs_.empty() && runs_.back().points.size() < 2) runs_.pop_back();
        runs_.push_back(ConvergenceRun{label, {point}});
        if (runs_.size() > MaxRuns) runs_.erase(runs_.begin());
        return;
    }
    std::vector<ConvergencePoint>& points = runs_.back().points;
    // The newest point stands in for its step until a later one has gone a whole step past the
    // point before it.
    if (points.size() >= 2 && points.back().spp < points[points.size() - 2].spp * SppStep)
        points.back() = point;
    else
        points.push_back(point);
}

LogRange ConvergenceHistory::axisRange(ConvergenceAxis axis) const {
    std::vector<double> values;
    for (const ConvergenceRun& run : runs_)
        for (const ConvergencePoint& p : run.points) values.push_back(axisValue(p, axis));
    return decadesAround(values);
}

LogRange ConvergenceHistory::metricRange(ConvergenceMetric metric) const {
    std::vector<double> values;
    for (const ConvergenceRun& run : runs_)
        for (const ConvergencePoint& p : run.points) values.push_back(metricValue(p, metric));
    return decadesAround(values);
}

LogLine ConvergenceHistory::guideLine(ConvergenceAxis axis, ConvergenceMetric metric,
                                      const LogRange& x) const {
    if (runs_.empty()) return LogLine{};
    const ConvergencePoint& anchor = runs_.back().points.back();
    const double ax = axisValue(anchor, axis), ay = metricValue(anchor, metric);
    if (!(ax > 0) || !(ay > 0)) return LogLine{};
    const double slope = guideSlope(metric);
    return LogLine{x.low, ay * std::pow(x.low / ax, slope), x.high,
                   ay * std::pow(x.high / ax, slope)};
}

} // namespace pathlab
