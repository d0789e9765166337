#pragma once
/// Three-component float vectors for positions, directions and normals.

#include <cmath>

namespace pathlab {

/// A point or direction in world space (scene units, e.g. millimetres in the Cornell box).
struct Vec3 {
    float x = 0, y = 0, z = 0;

    constexpr Vec3() = default;
    constexpr Vec3(float x, float y, float z) : x(x), y(y), z(z) {}

    constexpr float operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
    constexpr Vec3 operator-() const { return {-x, -y, -z}; }
    constexpr Vec3& operator+=(const Vec3& v) {
        x += v.x;
        y += v.y;
        z += v.z;
        return *this;
    }
};

/// Two uniform random numbers in [0,1)², as the sampler hands them out.
struct Vec2 {
    float x = 0, y = 0;
};

constexpr Vec3 operator+(const Vec3& a, const Vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
constexpr Vec3 operator-(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
constexpr Vec3 operator*(const Vec3& a, float s) { return {a.x * s, a.y * s, a.z * s}; }
constexpr Vec3 operator*(float s, const Vec3& a) { return a * s; }
constexpr Vec3 operator/(const Vec3& a, float s) { return a * (1.0f / s); }

constexpr float dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline float length(const Vec3& a) { return std::sqrt(dot(a, a)); }
inline Vec3 normalize(const Vec3& a) { return a / length(a); }
/// std::fmax, inline: GCC calls libm's fmaxf for it (NaN rule), and offsetRayOrigin runs per ray.
/// The larger of a and b, or whichever is not NaN.
constexpr float fmaxInline(float a, float b) { return (a > b || b != b) ? a : b; }
inline float maxAbsComponent(const Vec3& a) {
    return fmaxInline(std::fabs(a.x), fmaxInline(std::fabs(a.y), std::fabs(a.z)));
}

} // namespace pathlab
