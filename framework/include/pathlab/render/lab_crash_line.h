#pragma once
/// A lab that crashes the process says so in one line, as one that hangs does (the watchdog): a
/// recursion that never ends overflows its thread's stack within milliseconds, far sooner than
/// any watchdog, and the shell would say only "Segmentation fault".

#include "pathlab/render/render_watchdog.h"

namespace pathlab {

/// While one lives, SIGSEGV and SIGBUS in the process first write a line on stderr naming the
/// lab whose code runs and its file ("... crashed: a recursion that never ends, or a bad
/// pointer? ..."), then end it by the same signal as before, through the handler it replaced:
/// the exit status, and the grader's reading of it, are those of a crash. The handler runs on an
/// alternate stack of each thread that renders (an overflowed stack cannot run it): the thread
/// that makes it, and each of the renderer's as it starts a tile (prepareCrashStack). POSIX only;
/// elsewhere it does nothing.
class LabCrashLine {
public:
    explicit LabCrashLine(const WatchedLab& lab);
    ~LabCrashLine(); ///< restores the handlers it replaced
    LabCrashLine(const LabCrashLine&) = delete;
    LabCrashLine& operator=(const LabCrashLine&) = delete;

    /// The lab whose code now runs (the window switches labs between passes).
    static void running(const WatchedLab& lab);
    /// Gives the calling thread its alternate signal stack, once.
    static void prepareCrashStack();
};

} // namespace pathlab
