#pragma once
/// The rays a surface can send on: diffuse, mirror, refracted and glossy. Each needs a found
/// surface; `caller` is filled in by the compiler, so that a missed hit is reported at the
/// lab's line.

#include "pathlab/call_site.h"
#include "pathlab/hit.h"
#include "pathlab/ray.h"
#include "pathlab/vec3.h"

namespace pathlab {

/// A cosine-weighted diffuse bounce from `hit`, on the side the incoming ray came from.
/// Its contribution is weighted by Kd alone: cos θ / π of the integrand cancels against the
/// pdf cos θ / π (handout 01).
Ray diffuseRay(const Hit& hit, Vec2 u, CallSite caller = {});

/// The perfect mirror reflection of `ray` at `hit`.
Ray mirrorRay(const Ray& ray, const Hit& hit, CallSite caller = {});

/// The refraction of `ray` into (or out of) the surface at `hit`, using the material's Ni;
/// under total internal reflection it is the mirror ray instead, so no energy is lost.
Ray refractionRay(const Ray& ray, const Hit& hit, CallSite caller = {});

/// Lab 5: the ray leaving `hit` in `lobeDirection`, a direction given in the frame of
/// the glossy lobe (z along the mirror reflection of `ray`, as sampleLobe returns it), turned
/// into the world. It may point below the surface, where the lobe reaches past the horizon:
/// such a ray carries nothing (its cos θ is negative). `lobeDirection` must be a unit vector
/// with z >= 0: a check stops the render, naming the line, when it is not.
Ray glossyRay(const Ray& ray, const Hit& hit, Vec3 lobeDirection, CallSite caller = {});

/// Lab 6: `worldDirection` (a unit vector, such as a light sample's direction) in the frame of
/// the glossy lobe at `hit`, the inverse of glossyRay's turn: z is cos α, its cosine to the
/// mirror reflection of `ray`, as phongBrdf and lobePdf take it.
Vec3 lobeFrameDirection(const Ray& ray, const Hit& hit, Vec3 worldDirection, CallSite caller = {});

} // namespace pathlab
