// The window's convergence plot without its drawing (runner/convergence_history.h): runs split
// at restarts and new labels, points thinned to even steps in log spp, the plot's decades, the
// slope −1/2 guide line and the time to unit variance, against values worked out by hand.
#include "catch.h"

#include "runner/convergence_history.h"

#include <cmath>
#include <initializer_list>
#include <string>

using namespace pathlab;

namespace {

/// An unbiased estimator's point: relMSE = σ² / spp, seconds proportional to spp.
ConvergencePoint unbiasedPoint(int spp, double variance = 0.25, double secondsPerSpp = 0.01) {
    ConvergencePoint p;
    p.spp = spp;
    p.seconds = secondsPerSpp * spp;
    p.relMse = variance / spp;
    p.relativeRmse = std::sqrt(p.relMse);
    return p;
}

/// Adds unbiased points at these spp, in order, under `label`.
void addPoints(ConvergenceHistory& history, const std::string& label,
               std::initializer_list<int> spps) {
    for (int spp : spps) history.add(label, unbiasedPoint(spp));
}

} // namespace

TEST_CASE("a run lasts from one restart to the next, and every label has its own",
          "[render][convergence]") {
    ConvergenceHistory history;
    CHECK(history.current() == nullptr);
    for (int spp = 1; spp <= 4; ++spp) history.add("lab 1", unbiasedPoint(spp));
    REQUIRE(history.runs().size() == 1);
    CHECK(history.current()->points.size() == 4);

    // The spp went down with the same label: accumulation restarted (the r key, a camera move).
    addPoints(history, "lab 1", {1, 2});
    // Another lab: a run of its own, even if its spp went on rising.
    addPoints(history, "lab 2", {3, 4});
    REQUIRE(history.runs().size() == 3);
    CHECK(history.runs()[0].label == "lab 1");
    CHECK(history.runs()[1].label == "lab 1");
    CHECK(history.runs()[2].label == "lab 2");
    CHECK(history.current()->points.front().spp == 3);
}

TEST_CASE("a run of one point is forgotten when the next starts, and old runs go",
          "[render][convergence]") {
    ConvergenceHistory history;
    addPoints(history, "dragged", {1, 1, 1});
    addPoints(history, "kept", {1, 2});
    REQUIRE(history.runs().size() == 1);
    CHECK(history.runs()[0].label == "kept");

    for (size_t run = 0; run < ConvergenceHistory::MaxRuns + 3; ++run)
        addPoints(history, "run " + std::to_string(run), {1, 2});
    REQUIRE(history.runs().size() == ConvergenceHistory::MaxRuns);
    CHECK(history.current()->label == "run " + std::to_string(ConvergenceHistory::MaxRuns + 2));
}

TEST_CASE("points are kept at even steps in log spp, the newest always last",
          "[render][convergence]") {
    ConvergenceHistory history;
    for (int spp = 1; spp <= 1000; ++spp) history.add("lab 3", unbiasedPoint(spp));
    const std::vector<ConvergencePoint>& points = history.current()->points;
    // Roughly log(1000) / log(1.12) ≈ 61 points, not a thousand.
    CHECK(points.size() > 40);
    CHECK(points.size() < 80);
    CHECK(points.back().spp == 1000);
    for (size_t i = 1; i + 1 < points.size(); ++i)
        CHECK(points[i].spp >= points[i - 1].spp * ConvergenceHistory::SppStep);
}

TEST_CASE("the plot's ranges are whole decades around every run's points",
          "[render][convergence]") {
    CHECK(decadesAround({}).low == 1);
    CHECK(decadesAround({}).high == 10);
    const LogRange r = decadesAround({0.0, 0.03, 0.5, std::nan("")});
    CHECK(r.low == Approx(0.01));
    CHECK(r.high == Approx(1));
    const LogRange one = decadesAround({10.0});
    CHECK(one.low == Approx(10));
    CHECK(one.high == Approx(100));
    CHECK(r.position(0.1) == Approx(0.5));
    CHECK(r.position(1e-5) == 0);
    CHECK(r.position(50) == 1);

    ConvergenceHistory history;
    for (int spp = 1; spp <= 20; ++spp) history.add("a", unbiasedPoint(spp));
    for (int spp = 1; spp <= 300; ++spp) history.add("b", unbiasedPoint(spp, 4.0));
    const LogRange spp = history.axisRange(ConvergenceAxis::SamplesPerPixel);
    CHECK(spp.low == Approx(1));
    CHECK(spp.high == Approx(1000));
    const LogRange seconds = history.axisRange(ConvergenceAxis::Seconds);
    CHECK(seconds.low == Approx(0.01));
    CHECK(seconds.high == Approx(10));
    // relMSE from 0.25 / 20 = 0.0125 (a) and 4 / 300 = 0.0133 (b) up to 4 / 1 (b).
    const LogRange mse = history.metricRange(ConvergenceMetric::RelMse);
    CHECK(mse.low == Approx(0.01));
    CHECK(mse.high == Approx(10));
}

TEST_CASE("the guide line has slope -1/2 for the relative RMSE, -1 for relMSE, through the "
          "newest point",
          "[render][convergence]") {
    ConvergenceHistory history;
    CHECK(history.guideLine(ConvergenceAxis::Seconds, ConvergenceMetric::RelativeRmse, LogRange{})
              .x1 == 0);
    for (int spp = 1; spp <= 64; ++spp) history.add("lab 4", unbiasedPoint(spp));
    const ConvergencePoint& newest = history.current()->points.back();
    for (ConvergenceAxis axis : {ConvergenceAxis::SamplesPerPixel, ConvergenceAxis::Seconds})
        for (ConvergenceMetric metric :
             {ConvergenceMetric::RelativeRmse, ConvergenceMetric::RelMse}) {
            const LogRange x = history.axisRange(axis);
            const LogLine line = history.guideLine(axis, metric, x);
            CHECK(line.x0 == Approx(x.low));
            CHECK(line.x1 == Approx(x.high));
            const double slope = std::log(line.y1 / line.y0) / std::log(line.x1 / line.x0);
            CHECK(slope == Approx(guideSlope(metric)));
            // Through the newest point: y there is the point's own value.
            const double atNewest = line.y0 * std::pow(axisValue(newest, axis) / line.x0, slope);
            CHECK(atNewest == Approx(metricValue(newest, metric)));
            // An unbiased estimator's points lie on it.
            for (const ConvergencePoint& p : history.current()->points)
                CHECK(line.y0 * std::pow(axisValue(p, axis) / line.x0, slope) ==
                      Approx(metricValue(p, metric)));
        }
    CHECK(guideSlope(ConvergenceMetric::RelativeRmse) == -0.5);
    CHECK(guideSlope(ConvergenceMetric::RelMse) == -1);
}

TEST_CASE("the time to unit variance is relMSE x seconds, steady along an unbiased run",
          "[render][convergence]") {
    // σ² = 0.25 per spp, 0.01 s per spp: relMSE × t = 0.25 / n × 0.01 n = 0.0025 s.
    for (int spp : {1, 10, 100, 1000})
        CHECK(timeToUnitVariance(unbiasedPoint(spp)) == Approx(0.0025));
    CHECK(timeToUnitVariance(ConvergencePoint{}) == 0);
    // Against its own efficiency 1 / (relMSE × seconds): one over the other.
    const ConvergencePoint p = unbiasedPoint(37, 0.8, 0.02);
    CHECK(1 / timeToUnitVariance(p) == Approx(1 / (p.relMse * p.seconds)));
}
