#pragma once
/// Why the correctness check rejects a lab, in the words of its details and diagnosis: what
/// differs in each scene, and the likely cause the scenes can tell (the furnaces' values, the
/// refraction check, the mixed surfaces' channels, a lab not linear in light, a replayed pixel).

#include "checks/correctness_attempt.h"
#include "checks/grader_setup.h"

#include <cstdint>
#include <string>
#include <vector>

namespace pathlab::grader {

/// Whether any region (of a scene, or of all scenes) differs from its reference.
bool anyRejected(const std::vector<bool>& rejected);
/// The name a diagnosis goes by: the cause up to the explanation after the colon.
std::string causeName(const std::string& cause);

/// Explains a rejection (`rejected`: Holm's rejections over all scenes' regions in a row) in
/// `attempt`'s details and diagnosis: per scene, the whole image's observed/expected per channel
/// with a confidence interval, the tiles that differ, and a likely cause where the scenes can
/// tell. `seed` renders the linearity check and the replay.
void explainRejection(const GraderSetup& setup, Lab lab, const SceneComparisons& found,
                      const std::vector<bool>& rejected, uint64_t seed, Attempt& attempt);
/// Whether the regions of any public scene were rejected.
bool publicSceneRejected(const GraderSetup& setup, const SceneComparisons& found,
                         const std::vector<bool>& rejected);
/// Means that match from images that do not come from paths (path_evidence.h): says which
/// scenes in `attempt` and returns true; false where every scene's images are traced.
bool explainUntraced(const GraderSetup& setup, const SceneComparisons& found, Attempt& attempt);
/// Scenes whose renders spread from seed to seed too much to be judged (seed_spread.h): says
/// which in `attempt` and returns true; false where every scene could be judged.
bool explainTooNoisy(const GraderSetup& setup, const SceneComparisons& found, Attempt& attempt);

} // namespace pathlab::grader
