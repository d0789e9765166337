#include "pathlab/inspect/inspection_numbers.h"

#include <cstdio>

namespace pathlab {

std::string threeDigits(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    return text;
}

} // namespace pathlab
