// Hostile submission: a lab that never returns. Stopped by the per-run time limit.
#include "pathlab/lab.h"

namespace pathlab::branching {

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    volatile bool forever = true;
    while (forever) {
    }
    (void)ray, (void)depth, (void)ctx;
    return Color();
}

} // namespace pathlab::branching
