// Hostile submission: a static initializer that never returns, so loading this lab's code hangs.
// Each lab is loaded from a library of its own: only this lab may lose its points (batch_test.py
// submits the other three labs correct beside it).
#include "pathlab/lab.h"

namespace pathlab::branching {

namespace {

int waitForever() {
    volatile bool forever = true;
    while (forever) {
    }
    return 0;
}

const int neverSet = waitForever();

} // namespace

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    (void)ray, (void)depth, (void)ctx;
    return Color(static_cast<float>(neverSet));
}

} // namespace pathlab::branching
