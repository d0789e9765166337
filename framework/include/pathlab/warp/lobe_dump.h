#pragma once
/// What a lab's lobe routines gave for inputs the grader chose: sampleLobe's directions for the
/// numbers of a seeded stream, and lobePdf's values at seeded directions, per exponent. The lab's
/// process writes it (viewer --lobe-dump) and the grader reads and judges it in its own process
/// (phong_lobe_check.h): a lab's process can write anything, so nothing in the file is taken on
/// trust but the numbers, which only a right routine gets right.

#include "pathlab/vec3.h"

#include <cstdint>
#include <string>
#include <vector>

namespace pathlab {

/// The exponents a lobe is tested at (viewer --warp-test, and the grader's check): a lobe nearly
/// as wide as a diffuse one, and the two roughest plates of veach_plates. Sharper lobes fall
/// inside the first row of the warp test's cells, where it would see little.
inline const std::vector<float> WarpTestExponents = {1.0f, 12.0f, 60.0f};

/// The exponents the grader's check uses, drawn from its seed: one in [1, 2), one in [8, 24) and
/// one in [40, 100), so that a routine right only at the exponents a student can see tested
/// (WarpTestExponents) is not right at these.
std::vector<float> lobeCheckExponents(uint64_t seed);

/// Directions per exponent, and points at which the density is read.
constexpr uint32_t LobeDumpSamples = 200000;
constexpr uint32_t LobeDumpDensityPoints = 256;

struct LobeDumpExponent {
    float exponent = 0;
    std::vector<Vec3> samples;    ///< sampleLobe(u_i) for the stream's pairs u_i, in order
    std::vector<float> densities; ///< lobePdf at lobeCheckDirections(seed, exponent), in order
};

struct LobeDump {
    std::vector<LobeDumpExponent> exponents;
};

/// The i-th pair of numbers the samples are drawn for: the pairs of RandomStream(seed).
std::vector<Vec2> lobeDumpNumbers(uint64_t seed, uint32_t count);

/// The directions (in the lobe's frame) where the density is read: most within the lobe's width
/// for `exponent`, uniform in α there and in φ; one in eight below its plane, where the density
/// is 0; the axis itself first.
std::vector<Vec3> lobeCheckDirections(uint64_t seed, float exponent, uint32_t count);

/// The file's bytes: a header, then per exponent its value, counts, directions and densities
/// (little-endian float32).
std::string lobeDumpBytes(const LobeDump& dump);

/// The dump in `bytes`, which must hold exactly the exponents and counts asked for; otherwise
/// false with `problem` in words.
bool readLobeDump(const std::string& bytes, const std::vector<float>& exponents, LobeDump& dump,
                  std::string& problem);

} // namespace pathlab
