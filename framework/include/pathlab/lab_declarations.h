#pragma once
/// The declaration of every lab's pathTrace, in the namespace the build gives a lab file: the
/// build's bookkeeping, which lab.h includes so that a lab file needs nothing of its own.

#include "pathlab/color.h"
#include "pathlab/lab_list.h"
#include "pathlab/path_context.h"
#include "pathlab/ray.h"
#include "pathlab/vec3.h"

// The build compiles the student's labs/ and the reference solutions/ into one viewer, each set
// with its own PATHLAB_IMPL (student or solution) and each lab's name defined as that name with
// the set's appended (CMakeLists.txt: pathlab_lab_library, and the grader's build of a
// submission): `namespace pathlab::branching { ... }` in a lab file is pathlab::branching_student
// or pathlab::branching_solution, so the two sets, helpers included, never collide, and a lab
// file needs no macro of its own. (An inline namespace PATHLAB_IMPL around the lab namespaces
// would read better, but clang, Apple's included, mangles a reopened `namespace
// pathlab::branching` without it, and the sets would not link.)
#ifdef PATHLAB_IMPL
#define PATHLAB_DECLARE_PATH_TRACE(name, Enumerator, depthLimited)                                 \
    namespace pathlab::name {                                                                      \
    Color pathTrace(const Ray& ray, int depth, PathContext& ctx);                                  \
    }
PATHLAB_FOR_EACH_LAB(PATHLAB_DECLARE_PATH_TRACE)
#undef PATHLAB_DECLARE_PATH_TRACE
// A lab that writes a glossy lobe (lab 5) writes its sampling routine and density too: later
// labs call them as NAME::sampleLobe and NAME::lobePdf.
#define PATHLAB_DECLARE_LOBE(name, Enumerator)                                                     \
    namespace pathlab::name {                                                                      \
    Vec3 sampleLobe(Vec2 u, float exponent);                                                       \
    float lobePdf(Vec3 direction, float exponent);                                                 \
    }
PATHLAB_FOR_EACH_LOBE_LAB(PATHLAB_DECLARE_LOBE)
#undef PATHLAB_DECLARE_LOBE
#endif
