#include "pathlab/todo.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace pathlab {

namespace {
/// Bit N: a step of lab N reported itself.
std::atomic<unsigned> labsWithTodo{0};
} // namespace

void reportTodo(const char* file, int line, const char* step) {
    // "lab2.3": lab 2.
    if (std::strncmp(step, "lab", 3) == 0) {
        const long lab = std::strtol(step + 3, nullptr, 10);
        if (lab > 0 && lab < 32) labsWithTodo.fetch_or(1u << lab, std::memory_order_relaxed);
    }
    std::fprintf(stderr,
                 "%s:%d: TODO(%s) %s; this step adds nothing until you write it "
                 "(see the handout section %s)\n",
                 file, line, step, TodoNotDoneWords, step);
}

bool todoReported(int labNumber) {
    return labNumber > 0 && labNumber < 32 &&
           (labsWithTodo.load(std::memory_order_relaxed) & (1u << labNumber)) != 0;
}

} // namespace pathlab
