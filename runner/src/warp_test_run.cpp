#include "runner/warp_test_run.h"

#include "runner/lab_tables.h"

#include "pathlab/images/false_colour.h"
#include "pathlab/images/image_io.h"
#include "pathlab/render/lab_crash_line.h"
#include "pathlab/render/render_progress.h"
#include "pathlab/render/render_watchdog.h"
#include "pathlab/support/input_error.h"
#include "pathlab/support/whole_file.h"
#include "pathlab/warp/lobe_dump.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pathlab {

namespace {

/// Pixels per cell side in the picture.
constexpr int CellPixels = 6;
/// Pixels between panels and between rows.
constexpr int Gap = 6;

/// The lab's code running outside a render, watched as a render's: a routine that finishes no
/// sample for the watchdog's seconds ends the process with a line naming the lab, one that
/// crashes it says so. `progress` counts the routine's calls.
struct WatchedRoutines {
    WatchedRoutines(Lab lab, Implementation implementation, double watchdogSeconds)
        : watched{lab, implementation},
          watchdog(
              progress, watchdogSeconds, [w = watched] { return w; }, true),
          crashLine(watched) {}

    RenderProgress progress;
    WatchedLab watched;
    RenderWatchdog watchdog;
    LabCrashLine crashLine;
};

} // namespace

double warpCountScale(const WarpTestResult& r) {
    double highest = 1;
    for (size_t i = 0; i < r.observed.size(); ++i)
        highest = std::max({highest, r.observed[i], r.expected[i]});
    return highest;
}

void warpCellColour(const WarpTestResult& r, WarpPanel panel, size_t cell, double scale,
                    unsigned char* rgba) {
    if (panel == WarpPanel::Difference) {
        const double sd = std::sqrt(std::max(r.expected[cell], 1.0));
        divergingColour(static_cast<float>((r.observed[cell] - r.expected[cell]) / sd / 5), rgba);
        return;
    }
    const double value = panel == WarpPanel::Observed ? r.observed[cell] : r.expected[cell];
    heatColour(static_cast<float>(value / scale), rgba);
}

LobeRoutines lobeRoutinesToTest(Lab lab, Implementation implementation) {
    const LobeRoutines routines = findLobeRoutines(lab, implementation);
    if (!routines) {
        std::string labs;
        for (Lab each : AllLabs)
            if (findLobeRoutines(each, implementation))
                labs += (labs.empty() ? "" : ", ") + std::string(labName(each));
        throw InputError("the lab " + std::string(labName(lab)) +
                         " writes no lobe to test: --warp-test is for " +
                         (labs.empty() ? "a lab that writes sampleLobe and lobePdf" : labs));
    }
    return routines;
}

namespace {

/// One panel of the picture, its top left corner at (left, topRow).
void drawPanel(const WarpTestResult& result, WarpPanel panel, int left, int topRow, int width,
               std::vector<unsigned char>& rgb) {
    const SphereCells& cells = result.settings.cells;
    const double scale = warpCountScale(result);
    for (int cell = 0; cell < cells.count(); ++cell) {
        unsigned char colour[4];
        warpCellColour(result, panel, static_cast<size_t>(cell), scale, colour);
        const int x0 = left + (cell % cells.phiCells) * CellPixels;
        const int y0 = topRow + cells.thetaRow(cell) * CellPixels;
        for (int y = y0; y < y0 + CellPixels; ++y)
            for (int x = x0; x < x0 + CellPixels; ++x)
                std::copy(colour, colour + 3, &rgb[3 * (static_cast<size_t>(y) * width + x)]);
    }
}

} // namespace

LabWarpTests runLabWarpTests(Lab lab, Implementation implementation, uint64_t seed,
                             uint64_t samples, double watchdogSeconds) {
    const LobeRoutines routines = lobeRoutinesToTest(lab, implementation);
    LabWarpTests tests{lab, implementation, {}, true};
    WatchedRoutines watch(lab, implementation, watchdogSeconds);
    RenderProgress& progress = watch.progress;
    progress.passStarts(samples * WarpTestExponents.size());
    for (float exponent : WarpTestExponents) {
        WarpTestSettings settings;
        settings.samples = samples;
        settings.seed = seed;
        settings.alpha =
            sidakAlpha(WarpTestFalseFailRate, static_cast<int>(WarpTestExponents.size()));
        WarpSampling routine;
        routine.sample = [&](const Vec2& u) {
            progress.add(1);
            return routines.sample(u, exponent);
        };
        routine.density = [&](const Vec3& w) {
            return static_cast<double>(routines.density(w, exponent));
        };
        tests.exponents.push_back({exponent, runWarpTest(routine, settings)});
        tests.passed = tests.passed && tests.exponents.back().result.passed;
    }
    progress.passEnds();
    return tests;
}

void writeLobeDump(const std::string& path, Lab lab, Implementation implementation, uint64_t seed,
                   double watchdogSeconds) {
    const LobeRoutines routines = lobeRoutinesToTest(lab, implementation);
    WatchedRoutines watch(lab, implementation, watchdogSeconds);
    RenderProgress& progress = watch.progress;
    const std::vector<float> exponents = lobeCheckExponents(seed);
    progress.passStarts(uint64_t(LobeDumpSamples + LobeDumpDensityPoints) * exponents.size());
    const std::vector<Vec2> numbers = lobeDumpNumbers(seed, LobeDumpSamples);
    LobeDump dump;
    for (float exponent : exponents) {
        LobeDumpExponent& e = dump.exponents.emplace_back();
        e.exponent = exponent;
        for (const Vec2& u : numbers) {
            e.samples.push_back(routines.sample(u, exponent));
            progress.add(1);
        }
        for (const Vec3& w : lobeCheckDirections(seed, exponent, LobeDumpDensityPoints)) {
            e.densities.push_back(routines.density(w, exponent));
            progress.add(1);
        }
    }
    progress.passEnds();
    writeFileAtomically(path, lobeDumpBytes(dump));
}

std::string describeLabWarpTests(const LabWarpTests& tests) {
    std::string text;
    for (const LabWarpTest& test : tests.exponents) {
        char exponent[64];
        std::snprintf(exponent, sizeof exponent, "exponent %g: ", test.exponent);
        text += exponent + describeWarpTest(test.result) + "\n";
    }
    char verdict[256];
    std::snprintf(verdict, sizeof verdict,
                  "%s: sampleLobe and lobePdf of lab %s %s (a right pair fails with probability "
                  "%g)\n",
                  tests.passed ? "passed" : "FAILED", std::string(labName(tests.lab)).c_str(),
                  tests.passed ? "agree at every exponent" : "disagree", WarpTestFalseFailRate);
    return text + verdict;
}

void writeWarpTestImage(const std::string& path, const LabWarpTests& tests) {
    if (tests.exponents.empty()) return;
    const SphereCells& cells = tests.exponents.front().result.settings.cells;
    const int panelWidth = cells.phiCells * CellPixels, panelHeight = cells.thetaCells * CellPixels;
    const int width = 3 * panelWidth + 4 * Gap;
    const int rows = static_cast<int>(tests.exponents.size());
    const int height = rows * panelHeight + (rows + 1) * Gap;
    std::vector<unsigned char> rgb(3 * static_cast<size_t>(width) * height, 40);
    for (int row = 0; row < rows; ++row) {
        const WarpTestResult& r = tests.exponents[static_cast<size_t>(row)].result;
        const int top = Gap + row * (panelHeight + Gap);
        drawPanel(r, WarpPanel::Observed, Gap, top, width, rgb);
        drawPanel(r, WarpPanel::Expected, 2 * Gap + panelWidth, top, width, rgb);
        drawPanel(r, WarpPanel::Difference, 3 * Gap + 2 * panelWidth, top, width, rgb);
    }
    writeDisplayImage(path, width, height, rgb);
}

} // namespace pathlab
