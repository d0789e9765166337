#include "pathlab/scene_io/obj_fields.h"

#include <cmath>
#include <cstring>

namespace pathlab::objfields {

namespace {

bool isDigit(char c) { return static_cast<unsigned>(c - '0') < 10u; }

/// The decimal digits after the point, each added as digit × 10^-k (k from 1).
const char* readFraction(const char* at, const char* end, double& mantissa) {
    static const double powers[] = {1.0, 0.1, 0.01, 0.001, 0.0001, 0.00001, 0.000001, 0.0000001};
    const int tableSize = sizeof powers / sizeof powers[0];
    for (int k = 1; at != end && isDigit(*at); ++k, ++at)
        mantissa += static_cast<int>(*at - '0') * (k < tableSize ? powers[k] : std::pow(10.0, -k));
    return at;
}

/// The exponent after 'e' or 'E' (at `at`); false where it has no digits or overflows an int.
bool readExponent(const char* at, const char* end, int& exponent) {
    char sign = '+';
    if (at != end && (*at == '+' || *at == '-')) {
        sign = *at++;
    } else if (!isDigit(*at)) {
        return false;
    }
    int digits = 0;
    for (; at != end && isDigit(*at); ++at, ++digits) {
        if (exponent > 2147483647 / 10) return false;
        exponent = exponent * 10 + static_cast<int>(*at - '0');
    }
    exponent *= sign == '+' ? 1 : -1;
    return digits > 0;
}

/// [sign] digits [. digits] [(e|E) [sign] digits], or [sign] . digits ..., read greedily up to
/// the first character that does not fit; false where no number starts at `s`.
bool parseDouble(const char* s, const char* end, double* result) {
    if (s >= end) return false;
    double mantissa = 0.0;
    int exponent = 0;
    char sign = '+';
    const char* at = s;
    bool leadingDot = false;
    if (*at == '+' || *at == '-') {
        sign = *at++;
        leadingDot = at != end && *at == '.';
    } else if (*at == '.') {
        leadingDot = true;
    } else if (!isDigit(*at)) {
        return false;
    }
    bool more = at != end;
    if (!leadingDot) {
        int digits = 0;
        for (; more && isDigit(*at); ++digits, more = ++at != end)
            mantissa = mantissa * 10 + static_cast<int>(*at - '0');
        if (digits == 0) return false;
    }
    if (more && *at == '.') {
        at = readFraction(at + 1, end, mantissa);
        more = at != end;
    } else if (more && *at != 'e' && *at != 'E') {
        more = false; // the number ends here
    }
    if (more && (*at == 'e' || *at == 'E') && !readExponent(at + 1, end, exponent)) return false;
    *result = (sign == '+' ? 1 : -1) *
              (exponent ? std::ldexp(mantissa * std::pow(5.0, exponent), exponent) : mantissa);
    return true;
}

/// The field at `*token` after spaces and tabs: its end.
const char* fieldEnd(const char** token) {
    *token += std::strspn(*token, " \t");
    return *token + std::strcspn(*token, " \t\r");
}

} // namespace

float real(const char** token, double fallback) {
    const char* end = fieldEnd(token);
    double value = fallback;
    parseDouble(*token, end, &value);
    *token = end;
    return static_cast<float>(value);
}

bool real(const char** token, float* out) {
    const char* end = fieldEnd(token);
    double value = 0;
    const bool found = parseDouble(*token, end, &value);
    if (found) *out = static_cast<float>(value);
    *token = end;
    return found;
}

} // namespace pathlab::objfields
