#pragma once
/// PathLab's student API: everything a lab file uses, and nothing else.
///
/// A lab writes one function,
///
///     Color pathTrace(const Ray& ray, int depth, PathContext& ctx);
///
/// which returns the radiance arriving along `ray` (from the camera, depth 0, or from a surface
/// the path bounced off, depth > 0). It has at hand:
///
///   Types      Color (linear RGB: + - * / += *= /=, c[i], reduceMax, average, isBlack,
///              isFinite), Vec3 (+ - * / +=, dot, cross, length, normalize), Vec2, Ray (origin,
///              direction: unit length, kind), RayKind (Camera, Diffuse, Specular, Glossy),
///              Hit (found, position, normal, geometricNormal, frontFace, distance, material,
///              emitted), Material (Kd, Ks, Kt, Ni, Ke, Ns), LightSample, Strategy.
///   Tracing    ctx.trace(ray) -> Hit; ctx.directLight(hit) -> Color (next-event estimation).
///              A mistake these or the bounces can see (a missed hit, a direction that is not
///              unit length) stops the program with "labs/FILE.cpp:LINE: check failed: ...",
///              naming the line of your call (CallSite: the compiler fills it in).
///   Bounces    diffuseRay(hit, u), mirrorRay(ray, hit), refractionRay(ray, hit);
///              sampleCosineHemisphere(normal, u) underneath diffuseRay, and its density
///              cosineHemispherePdf.
///   Glossy     lab 5: a material with Ns > 0 has a glossy lobe where Ks is a mirror in
///              labs 1-4; glossyRay(ray, hit, d) leaves in the lobe's direction d, and
///              phongBrdf(m, cosAlpha) is its BRDF (handout 05).
///   MIS        lab 6: ctx.sampleLight(hit) -> LightSample (direction, distance, radiance,
///              pdf per unit solid angle, delta, cosAtLight); ctx.lightPdf(hit, onLight), the
///              density sampleLight would give a direction a ray found a light in;
///              lobeFrameDirection(ray, hit, direction), glossyRay's inverse;
///              ctx.strategyWeight(Strategy::Light or Lobe, weight) (handout 06).
///   Randomness ctx.sampler.get1D() -> float in [0,1), ctx.sampler.get2D() -> Vec2.
///   Parameters ctx.maxDepth (default 3), ctx.continueProb (default 0.1; labs 4-6).
///   Bookkeeping PATHLAB_TODO("lab1.2", depth) marks a step not written yet (and the names it
///              will use): it warns once, naming the file and line, and the program runs on.
///
/// The handouts (handouts/01-branching.md ...) explain the estimators each lab builds.

#include "pathlab/color.h"
#include "pathlab/constants.h"
#include "pathlab/cosine_hemisphere.h"
#include "pathlab/glossy_lobe.h"
#include "pathlab/hit.h"
#include "pathlab/lab_declarations.h"
#include "pathlab/light_sample.h"
#include "pathlab/material.h"
#include "pathlab/path_context.h"
#include "pathlab/ray.h"
#include "pathlab/sampler.h"
#include "pathlab/scattering.h"
#include "pathlab/todo.h"
#include "pathlab/vec3.h"
