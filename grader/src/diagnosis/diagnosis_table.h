#pragma once
/// The diagnoses and hints the grader gives students, as data: each names the step of the lab
/// it is about, as the lab file (TODO(lab3.1)) and its handout (### lab3.1) number it.

#include "common/by_lab.h"

#include "pathlab/render/lab_registry.h"

#include <optional>
#include <string>
#include <vector>

namespace pathlab::grader {

/// The parts of a lab that a diagnosis can point at; each lab numbers them its own way.
enum class LabStep {
    Emission,
    DepthLimit,
    FirstBounce,
    DiffuseWeight, ///< lab 1's diffuse bounce; the trace of the pick in labs 2-4
    Refraction,
    ProbabilityDivision, ///< labs 2-4 divide by the pick's probability (lab 4 by both)
    NearBlackStop,
};

/// The step's number in `lab` (3 for "TODO lab2.3"); 0: that lab has no such step.
int stepNumber(LabStep step, Lab lab);

/// "TODO lab3.1": the step as the lab file and its handout name it.
std::string todoName(LabStep step, Lab lab);

/// The labs a diagnosis or hint is about, as a set of bits (labBit).
using LabSet = unsigned;
constexpr LabSet labBit(Lab lab) { return 1u << static_cast<unsigned>(lab); }
constexpr LabSet EveryLab = (1u << LabCount) - 1;
/// The labs that end paths by Russian roulette (unbiased in the lab list: labs 4 and 5).
constexpr LabSet RouletteLabs = [] {
    LabSet labs = 0;
    for (Lab lab : AllLabs)
        if (!isDepthLimited(lab)) labs |= labBit(lab);
    return labs;
}();

/// How a (possibly wrong) lab behaves in a furnace, in the few numbers that decide its value.
struct FurnaceBehaviour {
    double diffuseWeight = 1; ///< a diffuse bounce's weight relative to Kd, in expectation
    double mirrorWeight = 1;  ///< a mirror bounce's weight relative to Ks, in expectation
    double directWeight = 1;  ///< next-event estimation's weight (none: 0)
    bool emissionAfterDiffuse = false;
    bool emissionAfterSpecular = true;
    int depthShift = 0;  ///< labs 1-3: bounces beyond (or short of) maxDepth
    int fixedDepth = -1; ///< labs 1-3: a depth limit of its own, whatever maxDepth is (-1: none)
    /// Lab 4: how often a path continued by a diffuse bounce, and by a mirror or refraction
    /// bounce, is divided by continueProb (each branch of the lab divides on its own).
    int rouletteDivisionsDiffuse = 1, rouletteDivisionsSpecular = 1;
    bool depthLimitKept = false; ///< lab 4: paths also end at maxDepth, as in labs 1-3
};

/// Which labs a known bug's sentence fits by the steps they have written: the stub's TODO
/// markers report themselves when they run (pathlab/todo.h), and a sentence about open steps
/// would mislead a student who has written them all.
enum class WrittenSteps {
    Any,
    SomeOpen, ///< the lab still reports a TODO step
    AllDone,  ///< the lab reports none
};

/// A bug students make, recognised by the values it gives in the furnaces.
struct KnownBug {
    /// The cause in a few words: feedback's diagnosis, by which a class's summary counts students.
    const char* diagnosis;
    /// After "diagnosis: ", what is wrong and what is right ("" for none). "{step}" stands for
    /// the step's TODO name; without it, " (TODO labL.S)" ends the sentence. "{depth}" stands for
    /// the depth a lab that ignores ctx.maxDepth renders at.
    const char* explanation;
    std::optional<LabStep> step;
    LabSet labs;
    void (*behave)(FurnaceBehaviour&);
    /// One candidate per maxDepth the furnaces were rendered at, each rendering at that one.
    bool perObservedDepth = false;
    WrittenSteps written = WrittenSteps::Any;

    /// Whether the sentence fits a lab that does (or does not) still report open steps.
    bool fits(bool stepsOpen) const {
        return written == WrittenSteps::Any || stepsOpen == (written == WrittenSteps::SomeOpen);
    }
};

/// Every known bug, best first where several explain the same values.
const std::vector<KnownBug>& knownBugs();

/// The sentence feedback gives for `bug` in `lab` ("diagnosis: explanation (TODO labL.S)");
/// `depth`: the depth of a perObservedDepth bug.
std::string bugSentence(const KnownBug& bug, Lab lab, int depth = -1);

/// What a hint explains, where the furnaces say nothing.
enum class HintTopic {
    NonfiniteRadiance, ///< NaN or infinite values in the image
    /// mixed_surfaces wrong, not its channels off in opposite ways; the furnaces and the
    /// refraction check right
    DiffuseDirection,
    /// mixed_surfaces wrong with some colour channel too bright and another too dark, the
    /// furnaces and the refraction check right; labs 2-4 only (lab 1 picks nothing)
    PickDivideMismatch,
    Refraction, ///< the view through the glass sphere wrong, the furnaces right
    TooNoisy,   ///< the noise check failed
};

struct Hint {
    HintTopic topic;
    LabSet labs;
    const char* text; ///< "{step}" as in KnownBug::explanation; without it, the step ends it
    std::optional<LabStep> step;
};

/// Every hint; per topic, the first whose labs hold a lab is that lab's.
const std::vector<Hint>& hints();

/// The hint on `topic` for `lab`, with its step named.
std::string hintFor(HintTopic topic, Lab lab);

} // namespace pathlab::grader
