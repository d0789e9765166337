#include "pathlab/render/lab_registry.h"

namespace pathlab {

std::string_view labName(Lab lab) {
    // Spelled by the preprocessor from the list, so a name cannot drift from its enumerator.
    constexpr std::string_view names[] = {
#define PATHLAB_LAB_NAME(name, Enumerator, depthLimited) #name,
        PATHLAB_FOR_EACH_LAB(PATHLAB_LAB_NAME)
#undef PATHLAB_LAB_NAME
    };
    return names[labIndex(lab)];
}

std::optional<Lab> labFromName(std::string_view name) {
    for (Lab lab : AllLabs)
        if (labName(lab) == name) return lab;
    return std::nullopt;
}

std::string labFileName(Lab lab) { return std::string(labName(lab)) + ".cpp"; }

std::string labNames(std::string_view separator) {
    std::string names;
    for (Lab lab : AllLabs) {
        if (!names.empty()) names += separator;
        names += labName(lab);
    }
    return names;
}

std::string_view implementationName(Implementation impl) {
    return impl == Implementation::Student ? "student" : "solution";
}

} // namespace pathlab
