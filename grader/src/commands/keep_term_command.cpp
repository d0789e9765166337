// grader keep-term OUT --term NAME --prior DIR: a graded class's lab files kept as normalised
// tokens (similarity/prior_terms.h), so that later terms' batches compare with it (--prior DIR)
// without keeping its code or comparing earlier terms among themselves.
#include "commands/commands.h"
#include "similarity/prior_terms.h"

#include "pathlab/support/input_error.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace pathlab::grader {

int keepTerm(const Arguments& a) {
    namespace fs = std::filesystem;
    const std::string out = a.inputs.front(), submissions = out + "/submissions";
    if (!fs::is_directory(submissions))
        throw InputError("grader keep-term: '" + out +
                         "' is not a batch's output (it has no submissions/ folder)");
    std::vector<std::string> ids;
    for (const auto& entry : fs::directory_iterator(submissions))
        if (entry.is_directory()) ids.push_back(entry.path().filename().string());
    std::sort(ids.begin(), ids.end());
    const int kept = keepPriorTerm(out, ids, a.term, a.prior);
    std::printf("kept %d lab file(s) of %zu submission(s) as tokens in %s/%s.json (no code): "
                "grader batch --prior %s compares later terms with them\n",
                kept, ids.size(), a.prior.c_str(), a.term.c_str(), a.prior.c_str());
    return 0;
}

} // namespace pathlab::grader
