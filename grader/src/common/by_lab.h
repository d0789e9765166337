#pragma once
/// One value per lab, looked up by Lab, so that no caller turns a Lab into an index itself.

#include "pathlab/render/lab_registry.h"

#include <array>
#include <cstddef>

namespace pathlab::grader {

/// A plain aggregate over an array in the order of AllLabs: `ByLab<int> spp = {8, 32, 16, 32}`
/// initialises it as the array would.
template <class T> struct ByLab {
    std::array<T, AllLabs.size()> values{};

    T& operator[](Lab lab) { return values[index(lab)]; }
    const T& operator[](Lab lab) const { return values[index(lab)]; }
    auto begin() const { return values.begin(); }
    auto end() const { return values.end(); }
    bool operator==(const ByLab& other) const { return values == other.values; }

private:
    static constexpr size_t index(Lab lab) { return static_cast<size_t>(lab); }
};

} // namespace pathlab::grader
