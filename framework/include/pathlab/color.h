#pragma once
/// RGB colours: radiance, albedos and throughputs, all linear (never sRGB-encoded).

#include <algorithm>
#include <cmath>

namespace pathlab {

/// A linear RGB triple. Radiance in W·sr⁻¹·m⁻² per channel, or a unitless reflectance.
struct Color {
    float r = 0, g = 0, b = 0;

    constexpr Color() = default;
    constexpr explicit Color(float v) : r(v), g(v), b(v) {}
    constexpr Color(float r, float g, float b) : r(r), g(g), b(b) {}

    constexpr float operator[](int i) const { return i == 0 ? r : (i == 1 ? g : b); }
    constexpr Color& operator+=(const Color& c) {
        r += c.r;
        g += c.g;
        b += c.b;
        return *this;
    }
    constexpr Color& operator*=(const Color& c) {
        r *= c.r;
        g *= c.g;
        b *= c.b;
        return *this;
    }
    constexpr Color& operator*=(float s) {
        r *= s;
        g *= s;
        b *= s;
        return *this;
    }
    constexpr Color& operator/=(float s) { return *this *= 1.0f / s; }
};

constexpr Color operator+(const Color& a, const Color& c) {
    return {a.r + c.r, a.g + c.g, a.b + c.b};
}
constexpr Color operator-(const Color& a, const Color& c) {
    return {a.r - c.r, a.g - c.g, a.b - c.b};
}
constexpr Color operator*(const Color& a, const Color& c) {
    return {a.r * c.r, a.g * c.g, a.b * c.b};
}
constexpr Color operator*(const Color& a, float s) { return {a.r * s, a.g * s, a.b * s}; }
constexpr Color operator*(float s, const Color& a) { return a * s; }
constexpr Color operator/(const Color& a, float s) { return a * (1.0f / s); }

/// The largest of the three channels: how strong a reflectance is, for picking components.
constexpr float reduceMax(const Color& c) { return std::max(c.r, std::max(c.g, c.b)); }
/// The channel average, used to weigh lights by power.
constexpr float average(const Color& c) { return (c.r + c.g + c.b) / 3.0f; }
/// True when every channel is zero: the component contributes nothing and needs no ray.
constexpr bool isBlack(const Color& c) { return c.r == 0 && c.g == 0 && c.b == 0; }
inline bool isFinite(const Color& c) {
    return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b);
}

} // namespace pathlab
