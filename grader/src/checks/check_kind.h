#pragma once
/// The checks a lab is graded by, and the one table of the names every report gives them.

#include <array>
#include <string_view>

namespace pathlab::grader {

/// In the order a lab is graded: correctness first, for noise and speed count only for a
/// correct lab.
enum class CheckKind { Correctness, Noise, Speed };
constexpr std::array<CheckKind, 3> AllChecks = {CheckKind::Correctness, CheckKind::Noise,
                                                CheckKind::Speed};

/// "correctness", "noise", "speed": the name in feedback.json, gradebook.csv's columns and
/// Gradescope's tests, which scripts outside the kit read.
constexpr std::string_view checkName(CheckKind check) {
    constexpr std::array<std::string_view, 3> names = {"correctness", "noise", "speed"};
    return names[static_cast<size_t>(check)];
}

} // namespace pathlab::grader
