#pragma once
/// What TBB guarantees a parallel_for, told to ThreadSanitizer: everything before it happens
/// before each task, and each task before everything after it. TBB hands tasks to its workers
/// and back inside libtbb, which is not instrumented, so TSan would otherwise take every read
/// of state made before the loop (a render pass's image, read by the next pass or by the
/// frame's hand-off) for a race. Nothing is said between tasks: a race between two tiles is
/// still reported. Without TSan these are nothing. (Private to the framework: the renderer and
/// the accumulation buffer use it.)
///
/// A hand-off is named by the address of a static object of the loop's function. A task must
/// name it before it has acquired anything, so not through the loop's closure: the closure lives
/// on the starting thread's stack, and a worker's read of it, unordered for TSan, raced with
/// whatever that thread had put at the same address before (seen now and then in a headless
/// render's image passes). Calls of the same loop on two threads at once share the name, which
/// can only hide a race between them, never report one that is not there.

#if defined(__SANITIZE_THREAD__)
#define PATHLAB_THREAD_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define PATHLAB_THREAD_SANITIZER 1
#endif
#endif
#ifdef PATHLAB_THREAD_SANITIZER
#include <sanitizer/tsan_interface.h>
#endif

namespace pathlab {

/// Before the loop (by the thread that starts it) and at the end of each task.
inline void releaseTo([[maybe_unused]] const void* handOff) {
#ifdef PATHLAB_THREAD_SANITIZER
    __tsan_release(const_cast<void*>(handOff));
#endif
}

/// At the start of each task, and after the loop (by the thread that started it).
inline void acquireFrom([[maybe_unused]] const void* handOff) {
#ifdef PATHLAB_THREAD_SANITIZER
    __tsan_acquire(const_cast<void*>(handOff));
#endif
}

} // namespace pathlab
