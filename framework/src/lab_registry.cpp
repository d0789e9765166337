#include "pathlab/lab_registry.h"

namespace pathlab {

std::string_view labName(Lab lab) {
    switch (lab) {
    case Lab::Branching: return "branching";
    case Lab::Uniform: return "uniform";
    case Lab::Importance: return "importance";
    case Lab::Roulette: return "roulette";
    }
    return "?";
}

std::optional<Lab> labFromName(std::string_view name) {
    for (Lab lab : AllLabs)
        if (labName(lab) == name) return lab;
    return std::nullopt;
}

std::string_view implementationName(Implementation impl) {
    return impl == Implementation::Student ? "student" : "solution";
}

} // namespace pathlab
