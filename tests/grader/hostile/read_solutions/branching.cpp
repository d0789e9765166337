// Hostile submission: reads the reference solution, the grader's references and the system's
// accounts. Each must be out of its sight; it reports what it found and aborts. @SOURCE@ is
// replaced by the test with the real source folder of the grading kit.
#include "pathlab/lab.h"

#include <cstdio>
#include <cstdlib>

namespace pathlab::branching {

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    for (const char* path : {"@SOURCE@/solutions/branching.cpp",
                             "@SOURCE@/grader/references/furnace.json", "/etc/passwd",
                             "/etc/shadow", "/root/.bash_history"}) {
        if (std::FILE* f = std::fopen(path, "r")) {
            std::fprintf(stderr, "read solutions: READ %s\n", path);
            std::fclose(f);
        } else {
            std::fprintf(stderr, "read solutions: cannot see %s\n", path);
        }
    }
    std::abort();
    (void)ray, (void)depth, (void)ctx;
}

} // namespace pathlab::branching
