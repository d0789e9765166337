#pragma once
/// The limits every render of a grading runs under.

#include "checks/grader_setup.h"

namespace pathlab::grader {

/// How many times a render's CPU limit its wall-clock limit is: the last resort, far beyond what
/// any load makes of a render that keeps finishing samples.
constexpr double WallLimitFactor = 10;

/// A render's limits from the rubric's seconds_per_run, `scale` times over (a longer render):
/// that much CPU time per render thread, half of it without a finished sample (the watchdog),
/// and WallLimitFactor times it of wall-clock time. None depends on how busy the machine is.
RenderLimits renderLimits(const Rubric& rubric, double scale = 1);

/// Each grading render's limits: renderLimits of the setup's rubric.
RenderLimits limitsOf(const GraderSetup& setup);

} // namespace pathlab::grader
