// A lab's rays per sample against the reference's, and the step of the lab's specification a
// difference points to.
#include "catch.h"
#include "messages.h"

#include "checks/rays_per_sample.h"

using namespace pathlab;
using namespace pathlab::grader;

TEST_CASE("rays per sample from the framework's counts", "[grader]") {
    const RaysPerSample rays = raysPerSample(RayCounters{3000, 1500}, 1000);
    CHECK(rays.camera == 1);
    CHECK(rays.bounce == Approx(2.0));
    CHECK(rays.shadow == Approx(1.5));
    CHECK(rays.shadowPerTrace() == Approx(0.5));
    CHECK(raysText(rays) == "1 camera + 2.00 bounce + 1.50 shadow");
    CHECK(raysPerSample(RayCounters{10, 10}, 0).camera == 0);
}

TEST_CASE("the specification each lab's extra bounce rays depart from", "[grader]") {
    const RaysPerSample reference{1, 0.93, 1.62};
    const RaysPerSample moreBounces{1, 2.14, 2.80};
    CHECK(contains(specificationDeparture(Lab::Uniform, moreBounces, reference),
                   "lab 2 picks among all three components, black ones included: probability "
                   "1/3 each"));
    CHECK(contains(specificationDeparture(Lab::Uniform, moreBounces, reference),
                   "2.14 bounce rays per sample against the reference's 0.93"));
    CHECK(contains(specificationDeparture(Lab::Branching, moreBounces, reference), "TODO lab1.3"));
    CHECK(contains(specificationDeparture(Lab::Importance, moreBounces, reference), "TODO lab3.3"));
    CHECK(contains(specificationDeparture(Lab::Roulette, moreBounces, reference), "TODO lab4.2"));
}

TEST_CASE("rays like the reference's depart from nothing; a noisy few percent neither",
          "[grader]") {
    const RaysPerSample reference{1, 0.93, 1.62};
    CHECK(specificationDeparture(Lab::Uniform, reference, reference).empty());
    CHECK(specificationDeparture(Lab::Uniform, {1, 0.95, 1.64}, reference).empty());
    // Fewer bounce rays is no departure for labs 1-3 (their correctness check judges the image).
    CHECK(specificationDeparture(Lab::Importance, {1, 0.5, 1.2}, reference).empty());
}

TEST_CASE("twice the shadow rays per hit, and roulette's short paths, are named", "[grader]") {
    const RaysPerSample reference{1, 0.93, 1.62};
    CHECK(contains(specificationDeparture(Lab::Branching, {1, 0.93, 3.24}, reference),
                   "next-event estimation runs more than once per hit"));
    CHECK(contains(specificationDeparture(Lab::Roulette, {1, 0.11, 0.9}, reference),
                   "ends paths sooner (a constant in place of ctx.continueProb?)"));
}
