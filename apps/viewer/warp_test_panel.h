#pragma once
/// The warp test in the window (the t key): the lab's sampleLobe against its lobePdf, as
/// `viewer --warp-test` runs it, with its verdict and, per exponent, the counts, the expected
/// counts and their difference drawn over the sphere's cells.

#include "runner/warp_test_run.h"

#include <optional>
#include <string>

namespace pathlab::viewer {

class WarpTestPanel {
public:
    explicit WarpTestPanel(double watchdogSeconds) : watchdogSeconds_(watchdogSeconds) {}

    /// Runs the test of `lab` in `implementation` now, on the calling thread: 200 000 directions
    /// per exponent, a fraction of a second. A lab that writes no lobe is said in the panel. The
    /// verdict is printed on stdout too.
    void run(Lab lab, Implementation implementation);
    /// Draws the panel, inside ImGui's frame, while it is open.
    void draw();

private:
    double watchdogSeconds_;
    std::optional<LabWarpTests> tests_;
    std::string text_; ///< the verdict in words, or why there is none
    bool open_ = false;
};

} // namespace pathlab::viewer
