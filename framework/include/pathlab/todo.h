#pragma once
/// PATHLAB_TODO: marks a lab step that is not written yet, without stopping the program.

#include <atomic>

namespace pathlab {

/// Prints "file:line: TODO(step) is not done yet ..." on standard error.
void reportTodo(const char* file, int line, const char* step);

} // namespace pathlab

/// Warns once per site, naming the file, line and step, then lets the render go on, so a
/// student can run the viewer before every step is written.
#define PATHLAB_TODO(step)                                                                         \
    do {                                                                                           \
        static std::atomic<bool> pathlabTodoReported{false};                                       \
        if (!pathlabTodoReported.load(std::memory_order_relaxed) &&                                \
            !pathlabTodoReported.exchange(true))                                                   \
            ::pathlab::reportTodo(__FILE__, __LINE__, step);                                       \
    } while (false)
