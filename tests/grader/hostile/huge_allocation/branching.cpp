// Hostile submission: allocates and touches 16 GB. Stopped by the memory limit.
#include "pathlab/lab.h"

#include <cstring>
#include <vector>

namespace pathlab::branching {

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    std::vector<char> hog(16ull << 30);
    std::memset(hog.data(), 1, hog.size());
    (void)ray, (void)depth, (void)ctx;
    return Color(hog[12345], 0, 0);
}

} // namespace pathlab::branching
