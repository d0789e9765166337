#include "pathlab/warp/lobe_dump.h"

#include "pathlab/random_stream.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace pathlab {

namespace {

constexpr char Header[8] = {'P', 'L', 'L', 'O', 'B', 'E', '1', '\n'};
constexpr double Pi = 3.14159265358979323846;

void put(std::string& out, const void* value, size_t bytes) {
    out.append(static_cast<const char*>(value), bytes);
}

/// Reads `bytes` bytes at `at` into `value`; false past the end.
bool take(const std::string& in, size_t& at, void* value, size_t bytes) {
    if (in.size() - at < bytes) return false;
    std::memcpy(value, in.data() + at, bytes);
    at += bytes;
    return true;
}

} // namespace

std::vector<Vec2> lobeDumpNumbers(uint64_t seed, uint32_t count) {
    RandomStream random(seed);
    std::vector<Vec2> numbers(count);
    for (Vec2& u : numbers) {
        const float x = random.nextFloat();
        u = {x, random.nextFloat()};
    }
    return numbers;
}

std::vector<float> lobeCheckExponents(uint64_t seed) {
    RandomStream random(seed ^ 0x5851f42d4c957f2dull);
    const float first = 1 + random.nextFloat(), second = 8 + 16 * random.nextFloat();
    return {first, second, 40 + 60 * random.nextFloat()};
}

std::vector<Vec3> lobeCheckDirections(uint64_t seed, float exponent, uint32_t count) {
    // A stream of its own, apart from the samples' numbers.
    RandomStream random(seed ^ 0x9e3779b97f4a7c15ull);
    // Three standard deviations of the lobe's α, or the whole hemisphere for a wide lobe.
    const double widest = std::min(Pi / 2, 3.0 / std::sqrt(exponent + 1.0));
    std::vector<Vec3> directions{{0, 0, 1}};
    while (directions.size() < count) {
        const bool below = directions.size() % 8 == 0;
        const double alpha =
            below ? Pi / 2 + random.nextFloat() * Pi / 2 : random.nextFloat() * widest;
        const double phi = 2 * Pi * random.nextFloat();
        directions.push_back({static_cast<float>(std::sin(alpha) * std::cos(phi)),
                              static_cast<float>(std::sin(alpha) * std::sin(phi)),
                              static_cast<float>(std::cos(alpha))});
    }
    return directions;
}

std::string lobeDumpBytes(const LobeDump& dump) {
    static_assert(sizeof(float) == 4 && sizeof(uint32_t) == 4);
    std::string out(Header, sizeof Header);
    const uint32_t exponents = static_cast<uint32_t>(dump.exponents.size());
    put(out, &exponents, 4);
    for (const LobeDumpExponent& e : dump.exponents) {
        const uint32_t samples = static_cast<uint32_t>(e.samples.size());
        const uint32_t points = static_cast<uint32_t>(e.densities.size());
        put(out, &e.exponent, 4);
        put(out, &samples, 4);
        put(out, &points, 4);
        for (const Vec3& w : e.samples) {
            put(out, &w.x, 4);
            put(out, &w.y, 4);
            put(out, &w.z, 4);
        }
        put(out, e.densities.data(), 4 * e.densities.size());
    }
    return out;
}

bool readLobeDump(const std::string& bytes, const std::vector<float>& exponents, LobeDump& dump,
                  std::string& problem) {
    size_t at = 0;
    char header[sizeof Header];
    uint32_t count = 0;
    if (!take(bytes, at, header, sizeof header) ||
        std::memcmp(header, Header, sizeof Header) != 0 || !take(bytes, at, &count, 4) ||
        count != exponents.size()) {
        problem = "it is not the lobe dump the viewer writes (its header or its number of "
                  "exponents)";
        return false;
    }
    dump.exponents.clear();
    for (float expected : exponents) {
        LobeDumpExponent e;
        uint32_t samples = 0, points = 0;
        if (!take(bytes, at, &e.exponent, 4) || !take(bytes, at, &samples, 4) ||
            !take(bytes, at, &points, 4) || e.exponent != expected || samples != LobeDumpSamples ||
            points != LobeDumpDensityPoints) {
            problem = "its exponents or counts are not those asked for";
            return false;
        }
        e.samples.resize(samples);
        e.densities.resize(points);
        for (Vec3& w : e.samples)
            if (!take(bytes, at, &w.x, 4) || !take(bytes, at, &w.y, 4) ||
                !take(bytes, at, &w.z, 4)) {
                problem = "it ends within its directions";
                return false;
            }
        if (!take(bytes, at, e.densities.data(), 4 * e.densities.size())) {
            problem = "it ends within its densities";
            return false;
        }
        dump.exponents.push_back(std::move(e));
    }
    if (at != bytes.size()) {
        problem = "it has bytes after its last exponent";
        return false;
    }
    return true;
}

} // namespace pathlab
