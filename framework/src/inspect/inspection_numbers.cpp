#include "pathlab/inspect/inspection_numbers.h"

#include <cstdio>

namespace pathlab {

std::string threeDigits(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    return text;
}

std::string compactColour(const Color& c) {
    if (c.r == c.g && c.g == c.b) return threeDigits(c.r);
    return threeDigits(c.r) + "," + threeDigits(c.g) + "," + threeDigits(c.b);
}

std::string materialText(const Material& m) {
    std::string text;
    const auto add = [&text](const char* name, const Color& c) {
        if (isBlack(c)) return;
        if (!text.empty()) text += " ";
        text += std::string(name) + " " + compactColour(c);
    };
    add("Kd", m.Kd);
    add("Ks", m.Ks);
    add("Kt", m.Kt);
    add("Ke", m.Ke);
    if (m.Ns > 0) text += " Ns " + threeDigits(m.Ns); // Ks is a glossy lobe (lab 5)
    return text.empty() ? "black" : text;
}

} // namespace pathlab
