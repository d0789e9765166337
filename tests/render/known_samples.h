#pragma once
// Samples whose statistics are worked out by hand, for the tests of what is computed from an
// AccumulationBuffer: the noise figure (noise_figure_test.cpp) and the noise and efficiency maps
// (reference_error_test.cpp) start from the same two pixels.
#include "pathlab/render/accumulation_buffer.h"

namespace pathlab::test {

/// Two pixels (2x1), four samples each, the same in every channel: pixel 0 sees 1, 3, 1, 3
/// (mean 2, sample variance 4/3), pixel 1 sees 0, 0, 0, 0 (a dark pixel: mean 0, variance 0).
inline AccumulationBuffer brightAndDarkPixel() {
    AccumulationBuffer buffer(2, 1);
    for (float v : {1.0f, 3.0f, 1.0f, 3.0f}) {
        buffer.addSample(0, Color(v));
        buffer.addSample(1, Color(0.0f));
    }
    buffer.finishPass(4);
    return buffer;
}

} // namespace pathlab::test
