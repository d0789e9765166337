#pragma once
/// What one render is, whoever asks for it: which lab, whose code, with what parameters, from
/// which seed, at what size. The viewer's options (RenderOptions), the window's settings
/// (ViewSettings) and what --stats records (RenderedWhat) are each one of these and more; the
/// grader's render requests carry one, and it crosses into a child viewer as one set of
/// arguments, written by renderIdentityArguments and read back by parseRenderOptions.

#include "pathlab/render/lab_parameters.h"
#include "pathlab/render/lab_registry.h"

#include <cstdint>
#include <string>
#include <vector>

namespace pathlab {

struct RenderIdentity {
    Lab lab = Lab::Branching;                                ///< --lab
    Implementation implementation = Implementation::Student; ///< --solution
    LabParameters parameters;                                ///< --max-depth, --continue-prob
    uint64_t seed = 0;                                       ///< --seed
    int width = 512, height = 512;                           ///< --size
};

bool operator==(const RenderIdentity& a, const RenderIdentity& b);
inline bool operator!=(const RenderIdentity& a, const RenderIdentity& b) { return !(a == b); }

/// "roulette (student)": the lab and whose code, as the inspector's table and lines name them.
std::string labAndImplementation(const RenderIdentity& identity);

/// The viewer's arguments that ask for `identity`: --lab, --solution for the solution, --max-depth,
/// --continue-prob (to the float's last bit), --seed and --size. parseRenderOptions reads them
/// back into the same identity.
std::vector<std::string> renderIdentityArguments(const RenderIdentity& identity);

} // namespace pathlab
