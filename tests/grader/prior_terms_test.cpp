// Earlier terms in the similarity report (similarity/prior_terms.h): a term is kept as tokens,
// no code; this term's copy of an earlier submission is paired with it; two earlier
// submissions alike are not paired with each other; a file that is not a kept term is named.
#include "catch.h"
#include "test_support.h"

#include "similarity/class_similarity.h"
#include "similarity/prior_terms.h"

#include "pathlab/support/input_error.h"
#include "pathlab/support/whole_file.h"

#include <algorithm>
#include <filesystem>

using namespace pathlab;
using namespace pathlab::grader;
using pathlab::test::ScratchFolder;
namespace fs = std::filesystem;

namespace {

/// A lab 1 unlike the solutions: the stub with steps of its own, named distinctly.
std::string ownBranching() {
    std::string text = readFile(std::string(PATHLAB_GRADER_DIR) + "/../labs/branching.cpp");
    std::string body;
    for (int k = 0; k < 40; ++k)
        body += "    float distinctiveName" + std::to_string(k) + " = radiance.x * " +
                std::to_string(k) + ".5f + (k" + std::to_string(k % 3) + " > 2 ? 1.0f : 0.25f);\n";
    return "static int k0 = 1, k1 = 2, k2 = 3;\nstatic void studentSteps(Vec3 radiance) {\n" +
           body + "}\n" + text;
}

void submit(const fs::path& out, const std::string& id, const std::string& text) {
    fs::create_directories(out / "submissions" / id / "submitted");
    writeFileAtomically((out / "submissions" / id / "submitted" / "branching.cpp").string(), text);
}

bool paired(const std::vector<SimilarLabs>& pairs, const std::string& a, const std::string& b) {
    return std::any_of(pairs.begin(), pairs.end(), [&](const SimilarLabs& p) {
        return (p.first == a && p.second == b) || (p.first == b && p.second == a);
    });
}

} // namespace

TEST_CASE("an earlier term is kept as tokens and compared with this term's files only",
          "[grader]") {
    ScratchFolder scratch("prior-terms");
    const fs::path earlier = scratch.path / "earlier", now = scratch.path / "now",
                   prior = scratch.path / "prior";
    submit(earlier, "bob", ownBranching());
    submit(earlier, "carol", ownBranching()); // bob's twin, in that term
    // The kit's solution, in that term (the student release has no solutions/).
    const std::string solution = std::string(PATHLAB_GRADER_DIR) + "/../solutions/branching.cpp";
    const bool kitHasSolutions = fs::is_regular_file(solution);
    if (kitHasSolutions) submit(earlier, "erin", readFile(solution));
    CHECK(keepPriorTerm(earlier.string(), {"bob", "carol", "erin"}, "2025-fall", prior.string()) ==
          (kitHasSolutions ? 3 : 2));
    const std::string kept = readFile((prior / "2025-fall.json").string());
    CHECK(kept.find("distinctiveName") == std::string::npos); // tokens, not code
    CHECK(kept.find("\"bob\"") != std::string::npos);

    submit(now, "alice", ownBranching()); // bob's file, handed in again this term
    submit(now, "dave", readFile(std::string(PATHLAB_GRADER_DIR) + "/../labs/branching.cpp"));
    const std::vector<SimilarLabs> pairs =
        similarSubmissions(now.string(), {"alice", "dave"}, prior.string());
    CHECK(paired(pairs, "alice", "2025-fall/bob"));
    CHECK(paired(pairs, "alice", "2025-fall/carol"));
    CHECK_FALSE(paired(pairs, "2025-fall/bob", "2025-fall/carol"));
    // An earlier copy of the solutions was told in its own term: not again.
    if (kitHasSolutions) CHECK_FALSE(paired(pairs, "2025-fall/erin", "reference solutions"));
    CHECK_FALSE(paired(pairs, "dave", "2025-fall/bob")); // the stub is alike to nothing
    CHECK(similarSubmissions(now.string(), {"alice", "dave"}).size() <= pairs.size());

    writeFileAtomically((prior / "notes.json").string(), "{\"hello\": 1}");
    try {
        priorTermFiles(prior.string());
        FAIL("a file that is not a kept term was read as one");
    } catch (const InputError& e) {
        CHECK(std::string(e.what()).find("notes.json: not an earlier term") != std::string::npos);
    }
    CHECK_THROWS_AS(keepPriorTerm(earlier.string(), {"bob"}, "../up", prior.string()), InputError);
}
