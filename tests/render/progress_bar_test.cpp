// The progress bar that reference measurements and batches print: a caller whose count of steps
// is off (the reference measurement counted 4 labs' noise renders when there were 7) must not
// stop the program. It did: a bar filled past its width asked for a string of negative length.
#include "catch.h"

#include "pathlab/support/progress_bar.h"

using namespace pathlab;

TEST_CASE("a progress bar told of more steps than its total draws a full bar", "[render]") {
    ProgressBar bar("reference for furnace", "renders");
    // In a log (not a terminal) it prints at each quarter: 40 of 32 is the fifth.
    CHECK_NOTHROW(bar.update(40, 32));
    CHECK_NOTHROW(bar.update(-1, 32));
    CHECK_NOTHROW(bar.update(5, 0));
}
