#pragma once
/// ThreadSanitizer's reports on a submitted lab, read: the data races with a frame in the lab's
/// own file, each named by that file's line and the memory raced on. What the race check
/// (race_check.h) found, and how it turns the correctness verdict (race_verdict.h).

#include <string>
#include <vector>

namespace pathlab::grader {

/// One data race between render threads, in the lab's own code.
struct LabRace {
    std::string line;     ///< where, as the student knows the file: "labs/uniform.cpp:23"
    std::string variable; ///< the static or global raced on ("counter"); "" for other memory
    bool heap = false;    ///< the memory was allocated on the heap (a pointer kept in a static?)

    /// One sentence for feedback: where, on what, and what to do instead.
    std::string text() const;
};

/// The data races in `output` (what a program run under TSan printed) whose stacks have a frame
/// in `fileInside` (the lab's path when it was compiled, e.g. "/submission/uniform.cpp"), each
/// named by the first such frame's line in `fileShown` ("labs/uniform.cpp"); one per line and
/// memory, in the order reported. Reports without such a frame (in the kit, TBB, Embree) are left
/// out: they are not the student's.
std::vector<LabRace> labRaces(const std::string& output, const std::string& fileInside,
                              const std::string& fileShown);

/// What the race check did for one lab.
struct RaceFinding {
    enum class Status {
        NotRun,      ///< no race check in this grading (not a submission, or no TSan here)
        Ran,         ///< the lab ran under TSan: `races` holds what it found, maybe nothing
        CouldNotRun, ///< it was tried and failed (`problem`); the lab is not failed for that
        /// The lab's library, compiled with ThreadSanitizer, would not load for a symbol it
        /// lacks, where the same file compiled without loaded: code that differs under the
        /// sanitizer (`problem`), held against the lab as a race would be.
        LabRefused
    } status = Status::NotRun;
    std::vector<LabRace> races;
    std::string problem;
    std::string how;    ///< what ran, for feedback: "ThreadSanitizer, the VI2 box at 64x64, ..."
    double seconds = 0; ///< compiling and running, for the instructor's figures
};

} // namespace pathlab::grader
