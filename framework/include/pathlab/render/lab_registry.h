#pragma once
/// The labs by name (the list is pathlab/lab_list.h), and whose code runs them.

#include "pathlab/lab_list.h"

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace pathlab {

/// The exercises, in the order the handouts teach them.
enum class Lab {
#define PATHLAB_LAB_ENUMERATOR(name, Enumerator, depthLimited) Enumerator,
    PATHLAB_FOR_EACH_LAB(PATHLAB_LAB_ENUMERATOR)
#undef PATHLAB_LAB_ENUMERATOR
};

constexpr std::size_t LabCount = 0
#define PATHLAB_LAB_ONE(name, Enumerator, depthLimited) +1
    PATHLAB_FOR_EACH_LAB(PATHLAB_LAB_ONE)
#undef PATHLAB_LAB_ONE
    ;

constexpr std::array<Lab, LabCount> AllLabs = {
#define PATHLAB_LAB_VALUE(name, Enumerator, depthLimited) Lab::Enumerator,
    PATHLAB_FOR_EACH_LAB(PATHLAB_LAB_VALUE)
#undef PATHLAB_LAB_VALUE
};

/// The lab's position in AllLabs, for arrays kept per lab.
constexpr std::size_t labIndex(Lab lab) { return static_cast<std::size_t>(lab); }

/// The lab's number in the handouts and in its steps' names (lab1.3): its line in the lab list,
/// counted from 1.
constexpr int labNumber(Lab lab) { return static_cast<int>(labIndex(lab)) + 1; }

/// Whose code runs: the student's labs/ or the reference solutions/.
enum class Implementation { Student, Solution };

/// "branching", "uniform", "importance", "roulette": the lab's file, namespace and --lab name.
std::string_view labName(Lab lab);
std::optional<Lab> labFromName(std::string_view name);
/// "roulette.cpp": the lab's file, in labs/ and solutions/ and in a submission.
std::string labFileName(Lab lab);
/// Every lab's name, in order, between `separator`s: "branching, uniform, ...".
std::string labNames(std::string_view separator);
/// "student" or "solution".
std::string_view implementationName(Implementation impl);

/// Labs 1–3 stop at maxDepth and estimate the same depth-limited image; lab 4 is unbiased.
constexpr bool isDepthLimited(Lab lab) {
    constexpr bool limited[] = {
#define PATHLAB_LAB_LIMITED(name, Enumerator, depthLimited) depthLimited,
        PATHLAB_FOR_EACH_LAB(PATHLAB_LAB_LIMITED)
#undef PATHLAB_LAB_LIMITED
    };
    return limited[labIndex(lab)];
}

/// Whether the lab writes a glossy lobe's sampling routine and density beside pathTrace (lab 5;
/// `lobe` in the lab list), which the warp test checks.
constexpr bool writesLobe(Lab lab) {
    bool lobe[LabCount] = {};
#define PATHLAB_LAB_WRITES_LOBE(name, Enumerator) lobe[labIndex(Lab::Enumerator)] = true;
    PATHLAB_FOR_EACH_LOBE_LAB(PATHLAB_LAB_WRITES_LOBE)
#undef PATHLAB_LAB_WRITES_LOBE
    return lobe[labIndex(lab)];
}

} // namespace pathlab
