#include "diagnosis/diagnosis_table.h"

#include <array>

namespace pathlab::grader {

namespace {

constexpr double Pi = 3.14159265358979;

/// Labs 2-4 trace the picked component and weigh it in one step (lab 4 divides by both of its
/// probabilities in step 4.4); lab 4 has no depth limit; labs 1-2 pick nothing that can be
/// black, so they have no near-black stop. Lab 5 has all of lab 4's in its step 5.3 ("as your
/// lab 4"), lab 6 in its step 6.5 ("your lab 5 path"); their own steps, the lobe's, are told by
/// the lobe check (checks/lobe_check.h), lab 6's weights by the lab tests and the noise check.
const std::array<ByLab<int>, 7> StepNumbers = {{
    {1, 1, 1, 1, 3, 5}, // Emission
    {2, 2, 2, 2, 3, 5}, // DepthLimit (lab 4's step 2 replaces it with roulette)
    {3, 3, 3, 2, 3, 5}, // FirstBounce
    {3, 4, 4, 4, 3, 5}, // DiffuseWeight
    {5, 4, 4, 3, 3, 5}, // Refraction
    {0, 4, 4, 4, 3, 5}, // ProbabilityDivision
    {0, 0, 3, 3, 3, 5}, // NearBlackStop
}};

constexpr LabSet DepthLimited = EveryLab & ~RouletteLabs;
constexpr LabSet WithNearBlackStop = labBit(Lab::Importance) | RouletteLabs;

std::string replaced(std::string text, const std::string& placeholder, const std::string& by) {
    if (const size_t at = text.find(placeholder); at != std::string::npos)
        text.replace(at, placeholder.size(), by);
    return text;
}

/// `text` with its step named: in place of "{step}", or at the end.
std::string withStep(const std::string& text, const std::optional<LabStep>& step, Lab lab) {
    if (!step) return text;
    if (text.find("{step}") != std::string::npos)
        return replaced(text, "{step}", todoName(*step, lab));
    return text + " (" + todoName(*step, lab) + ")";
}

} // namespace

int stepNumber(LabStep step, Lab lab) { return StepNumbers[static_cast<size_t>(step)][lab]; }

std::string todoName(LabStep step, Lab lab) {
    return "TODO lab" + std::to_string(static_cast<int>(lab) + 1) + "." +
           std::to_string(stepNumber(step, lab));
}

const std::vector<KnownBug>& knownBugs() {
    static const std::vector<KnownBug> bugs = {
        {"no bounce rays yet",
         "the lab renders direct light only (its steps from {step} on are "
         "still open)",
         LabStep::FirstBounce, EveryLab,
         [](FurnaceBehaviour& b) { b.diffuseWeight = b.mirrorWeight = 0; }, false,
         WrittenSteps::SomeOpen},
        // The same values from a lab whose steps are all written: what it does, not the stub.
        {"bounces add nothing",
         "the lab renders direct light only, although no step is left open: no bounce is traced, "
         "or each adds 0. Is a probability or a weight 0 where it should not be? In C++ 1 / 3 "
         "divides integers and is 0 (write 1.0f / 3); a pick that compares u with 0 never "
         "picks (from {step} on)",
         LabStep::FirstBounce, EveryLab,
         [](FurnaceBehaviour& b) { b.diffuseWeight = b.mirrorWeight = 0; }, false,
         WrittenSteps::AllDone},
        {"emission after a specular bounce missing",
         "a ray that left a mirror or a refraction "
         "(RayKind::Specular) must add hit.emitted, since next-event estimation never finds a "
         "light in one exact direction",
         LabStep::Emission, EveryLab, [](FurnaceBehaviour& b) { b.emissionAfterSpecular = false; }},
        {"emission counted twice",
         "it is added after diffuse bounces too, although next-event "
         "estimation already counted it",
         LabStep::Emission, EveryLab, [](FurnaceBehaviour& b) { b.emissionAfterDiffuse = true; }},
        {"no next-event estimation", "ctx.directLight(hit), given in the lab file, is missing",
         std::nullopt, EveryLab, [](FurnaceBehaviour& b) { b.directWeight = 0; }},
        // Lab 4 without next-event estimation but with emission after every bounce is still
        // unbiased: the same mean, in every furnace, as a correct one.
        {"no next-event estimation, with emission added after every bounce instead",
         "emission "
         "belongs after camera and specular rays only, beside ctx.directLight(hit)",
         LabStep::Emission, DepthLimited,
         [](FurnaceBehaviour& b) { b.directWeight = 0, b.emissionAfterDiffuse = true; }},
        {"a factor of pi",
         "the diffuse bounce is weighted by pi*Kd; with cosine sampling the "
         "weight is Kd alone",
         LabStep::DiffuseWeight, EveryLab, [](FurnaceBehaviour& b) { b.diffuseWeight = Pi; }},
        {"a factor of 1/pi",
         "the diffuse bounce is weighted by Kd/pi; with cosine sampling the "
         "weight is Kd alone",
         LabStep::DiffuseWeight, EveryLab, [](FurnaceBehaviour& b) { b.diffuseWeight = 1 / Pi; }},
        {"direct light weighted by an extra pi", "", std::nullopt, EveryLab,
         [](FurnaceBehaviour& b) { b.directWeight = Pi; }},
        {"depth off by one",
         "one bounce too many: return before the bounce when depth >= "
         "ctx.maxDepth (the primary hit is depth 0)",
         LabStep::DepthLimit, DepthLimited, [](FurnaceBehaviour& b) { b.depthShift = 1; }},
        {"depth off by one", "one bounce too few: the primary hit is depth 0", LabStep::DepthLimit,
         DepthLimited, [](FurnaceBehaviour& b) { b.depthShift = -1; }},
        // Furnaces at two maxDepths tell a lab that ignores it: it renders one of them right.
        {"ctx.maxDepth ignored",
         "the lab renders as if maxDepth were {depth}, whatever "
         "ctx.maxDepth says (a constant in its place?)",
         LabStep::DepthLimit, DepthLimited, [](FurnaceBehaviour&) {}, true},
        // A wrong pick weight scales whichever component is picked.
        {"forgot to divide by the pick probability 1/3", "", LabStep::ProbabilityDivision,
         labBit(Lab::Uniform),
         [](FurnaceBehaviour& b) { b.diffuseWeight = b.mirrorWeight = 1.0 / 3; }},
        // One branch of the lab's own: the diffuse furnaces read the value above, the mirror
        // furnace a correct lab's (or the other way round). A factor of 1/pi (0.318) in the
        // diffuse branch gives values close to 1/3's: the closer fit is told first.
        {"forgot to divide by the pick probability 1/3 in the diffuse branch",
         "the Ks and Kt branches divide by it, the Kd branch does not; each branch must",
         LabStep::ProbabilityDivision, labBit(Lab::Uniform),
         [](FurnaceBehaviour& b) { b.diffuseWeight = 1.0 / 3; }},
        {"forgot to divide by the pick probability 1/3 in the mirror and refraction branches",
         "the Kd branch divides by it, the Ks and Kt branches do not; each branch must",
         LabStep::ProbabilityDivision, labBit(Lab::Uniform),
         [](FurnaceBehaviour& b) { b.mirrorWeight = 1.0 / 3; }},
        // 1/2 where the pick is 1/3: the three components read as two.
        {"divided by 1/2 instead of the pick probability 1/3", "", LabStep::ProbabilityDivision,
         labBit(Lab::Uniform),
         [](FurnaceBehaviour& b) { b.diffuseWeight = b.mirrorWeight = 2.0 / 3; }},
        {"divided by the pick probability twice", "", LabStep::ProbabilityDivision,
         labBit(Lab::Uniform), [](FurnaceBehaviour& b) { b.diffuseWeight = b.mirrorWeight = 3; }},
        {"divided by 1/3 instead of the chosen component's probability", "",
         LabStep::ProbabilityDivision, labBit(Lab::Importance),
         [](FurnaceBehaviour& b) { b.diffuseWeight = b.mirrorWeight = 3; }},
        // Lab 3's depth test kept above lab 4's roulette: unbiased up to maxDepth, so the
        // furnaces read the depth-limited values of labs 1-3.
        {"a depth limit is still there",
         "lab 4 ends paths only by roulette; a test of depth against ctx.maxDepth, kept from lab "
         "3, cuts every path at maxDepth and darkens the image",
         LabStep::DepthLimit, RouletteLabs, [](FurnaceBehaviour& b) { b.depthLimitKept = true; }},
        {"Russian-roulette weight missing", "a continued path must be divided by continueProb",
         LabStep::ProbabilityDivision, RouletteLabs,
         [](FurnaceBehaviour& b) { b.rouletteDivisionsDiffuse = b.rouletteDivisionsSpecular = 0; }},
        {"divided by continueProb twice", "", LabStep::ProbabilityDivision, RouletteLabs,
         [](FurnaceBehaviour& b) { b.rouletteDivisionsDiffuse = b.rouletteDivisionsSpecular = 2; }},
        // One branch of the lab's own: the mirror furnace reads 1/(1 - s*q) where a correct lab
        // gives 1/(1 - s), the diffuse furnaces are right (or the other way round).
        {"Russian-roulette weight missing on the mirror and refraction branches",
         "the diffuse branch divides a continued path by continueProb, the Ks and Kt branches do "
         "not; each branch must",
         LabStep::ProbabilityDivision, RouletteLabs,
         [](FurnaceBehaviour& b) { b.rouletteDivisionsSpecular = 0; }},
        {"Russian-roulette weight missing on the diffuse branch",
         "the Ks and Kt branches divide a continued path by continueProb, the diffuse branch does "
         "not; each branch must",
         LabStep::ProbabilityDivision, RouletteLabs,
         [](FurnaceBehaviour& b) { b.rouletteDivisionsDiffuse = 0; }},
        {"divided by continueProb twice on the mirror and refraction branches", "",
         LabStep::ProbabilityDivision, RouletteLabs,
         [](FurnaceBehaviour& b) { b.rouletteDivisionsSpecular = 2; }},
        {"divided by continueProb twice on the diffuse branch", "", LabStep::ProbabilityDivision,
         RouletteLabs, [](FurnaceBehaviour& b) { b.rouletteDivisionsDiffuse = 2; }},
    };
    return bugs;
}

std::string bugSentence(const KnownBug& bug, Lab lab, int depth) {
    std::string text = bug.diagnosis;
    if (*bug.explanation) text += std::string(": ") + bug.explanation;
    return withStep(replaced(text, "{depth}", std::to_string(depth)), bug.step, lab);
}

const std::vector<Hint>& hints() {
    static const std::vector<Hint> all = {
        {HintTopic::NonfiniteRadiance, WithNearBlackStop,
         "a division by zero: on a surface with no component at all (the light's material has "
         "only Ke) the strengths sum to 0 and total/strength is 0/0; the near-black stop must "
         "return before the pick",
         LabStep::NearBlackStop},
        {HintTopic::NonfiniteRadiance, EveryLab,
         "a division by zero (0/0 is NaN, x/0 infinite; in C++ 1 / 3 divides integers and is 0: "
         "write 1.0f / 3) or a value used before it is set, in the lab's own arithmetic",
         std::nullopt},
        {HintTopic::DiffuseDirection, EveryLab,
         "diffuse directions drawn from part of the hemisphere: on surfaces that are part "
         "diffuse, part mirror or glass, lit from one side, the image differs; is a random number "
         "used twice (the pick's u again in diffuseRay's u, or one number for both of its "
         "coordinates), or the direction drawn around a normal that does not face the incoming "
         "ray? diffuseRay(hit, ctx.sampler.get2D()) with a fresh get2D() after the pick",
         LabStep::DiffuseWeight},
        {HintTopic::PickDivideMismatch, labBit(Lab::Uniform),
         "pick and division disagree: the probability you divide by must be the one you picked "
         "with, 1/3 for each of the three components; on mixed_surfaces, whose red diffuse "
         "components sit beside teal mirrors and cyan glass, a lab that divides by any other "
         "number makes some colour channels too bright and others too dark",
         LabStep::ProbabilityDivision},
        {HintTopic::PickDivideMismatch, labBit(Lab::Importance) | RouletteLabs,
         "pick and division disagree: the probability you divide by must be the one you picked "
         "with; on mixed_surfaces, whose red diffuse components sit beside teal mirrors and cyan "
         "glass, strengths by luminance, channel sum or average give other probabilities than "
         "by reduceMax, so a lab that picks by one and divides by the other's probability makes "
         "some colour channels too bright and others too dark; compute the strengths once and "
         "use them for both",
         LabStep::ProbabilityDivision},
        {HintTopic::Refraction, EveryLab,
         "the view through the glass sphere is wrong: the Kt component must trace "
         "refractionRay(ray, hit), which bends the ray by Ni and turns into a mirror ray under "
         "total internal reflection",
         LabStep::Refraction},
        {HintTopic::TooNoisy, labBit(Lab::Importance),
         "an importance pick that picks uniformly, or that picks components whose reflectance is "
         "zero, is this noisy; the probabilities should follow reduceMax(Kd), reduceMax(Ks), "
         "reduceMax(Kt)",
         std::nullopt},
        {HintTopic::TooNoisy, RouletteLabs,
         "Russian roulette should pick the component by importance, as in lab 3", std::nullopt},
        {HintTopic::TooNoisy, EveryLab,
         "more noise than the reference at the same mean: is a component sampled with the wrong "
         "probability, or a random number reused?",
         std::nullopt},
    };
    return all;
}

std::string hintFor(HintTopic topic, Lab lab) {
    for (const Hint& hint : hints())
        if (hint.topic == topic && (hint.labs & labBit(lab)))
            return withStep(hint.text, hint.step, lab);
    return "";
}

} // namespace pathlab::grader
