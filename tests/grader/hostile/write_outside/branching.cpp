// Hostile submission: writes outside its scratch folder, in every place a sandbox could leave
// open. Each attempt must fail; the lab reports the failures and aborts, so that its feedback
// shows them. @OUTSIDE@ is replaced by the test with a folder of the host that must stay empty.
#include "pathlab/lab.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace pathlab::branching {

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    for (const char* path : {"@OUTSIDE@/written_by_a_submission", "/tmp/written_by_a_submission",
                             "/written_by_a_submission", "/usr/written_by_a_submission",
                             "/dev/written_by_a_submission", "../written_by_a_submission"}) {
        if (std::FILE* f = std::fopen(path, "w")) {
            std::fprintf(stderr, "write outside: WROTE %s\n", path);
            std::fclose(f);
        } else {
            std::fprintf(stderr, "write outside: cannot write %s: %s\n", path, std::strerror(errno));
        }
    }
    std::abort();
    (void)ray, (void)depth, (void)ctx;
}

} // namespace pathlab::branching
