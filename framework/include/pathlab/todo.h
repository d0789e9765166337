#pragma once
/// PATHLAB_TODO: marks a lab step that is not written yet, without stopping the program.

#include <atomic>

namespace pathlab {

/// The words of reportTodo's line by which a program that ran a lab (the grader, reading a
/// render's output) tells that the lab still has a step not written.
inline constexpr const char* TodoNotDoneWords = "is not done yet";

/// Prints "file:line: TODO(step) is not done yet ..." on standard error.
void reportTodo(const char* file, int line, const char* step);

/// Whether this process has run a step of lab `labNumber` (1 for "lab1.2") that is not written
/// yet: the lab tests tell by it whether the lab they render is still a stub in part.
bool todoReported(int labNumber);

/// Marks the site of one step: warns once (the flag is the site's own), naming the file, line
/// and step. `namesTheStepUses` are the variables the step will read (`depth`, `m`): naming them
/// here keeps the compiler from warning that they are unused while the step is not written, and
/// the warning comes back if the step's line is deleted and the step still does not use them.
template <class... Names>
inline void markTodo(std::atomic<bool>& reported, const char* file, int line, const char* step,
                     const Names&... namesTheStepUses) {
    ((void)namesTheStepUses, ...);
    if (!reported.load(std::memory_order_relaxed) && !reported.exchange(true))
        reportTodo(file, line, step);
}

} // namespace pathlab

/// PATHLAB_TODO("lab1.2", depth): step lab1.2 is not written yet, and will use `depth`. Warns
/// once per site, naming the file, line and step, then lets the render go on, so a student can
/// run the viewer before every step is written.
#define PATHLAB_TODO(...)                                                                          \
    do {                                                                                           \
        static std::atomic<bool> pathlabTodoReported{false};                                       \
        ::pathlab::markTodo(pathlabTodoReported, __FILE__, __LINE__, __VA_ARGS__);                 \
    } while (false)
