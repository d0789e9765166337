#pragma once
/// The start-up of renders (loading the scene, building Embree's BVH), measured once per grading:
/// the speed check subtracts it from every timed run, and the time limits scale with it.

#include <functional>
#include <map>
#include <string>

namespace pathlab::grader {

/// Made by whoever starts a grading and passed down to the checks, so that a measurement lives
/// exactly as long as that grading and no longer (a later grading measures afresh).
class StartUpTimes {
public:
    /// The seconds measured for `what` (a scene, lab, viewer, library and thread count), taken
    /// from `measure` the first time they are asked for.
    double seconds(const std::string& what, const std::function<double()>& measure);

private:
    std::map<std::string, double> measured_;
};

} // namespace pathlab::grader
