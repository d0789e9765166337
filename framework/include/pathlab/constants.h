#pragma once

namespace pathlab {

constexpr float Pi = 3.14159265358979323846f;
constexpr float InvPi = 0.31830988618379067154f;

} // namespace pathlab
