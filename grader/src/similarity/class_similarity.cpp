#include "similarity/class_similarity.h"

#include "similarity/prior_terms.h"
#include "similarity/similarity.h"

#include "pathlab/render/lab_registry.h"
#include "pathlab/support/whole_file.h"

#include <filesystem>
#include <map>

namespace pathlab::grader {

namespace fs = std::filesystem;

std::vector<SimilarLabs> similarSubmissions(const std::string& out,
                                            const std::vector<std::string>& ids,
                                            const std::string& priorDir) {
    const fs::path kit = fs::path(PATHLAB_GRADER_DIR).parent_path();
    std::vector<SubmittedFile> files;
    std::map<std::string, std::string> stubs;
    for (Lab lab : AllLabs) {
        const std::string name = std::string(labName(lab)), file = labFileName(lab);
        stubs[name] = readFile((kit / "labs" / file).string());
        if (fs::is_regular_file(kit / "solutions" / file))
            files.push_back({KitSolutions, name, readFile((kit / "solutions" / file).string())});
        for (const std::string& id : ids) {
            const fs::path submitted = fs::path(out) / "submissions" / id / "submitted" / file;
            if (fs::is_regular_file(submitted))
                files.push_back({id, name, readFile(submitted.string())});
        }
    }
    if (!priorDir.empty())
        for (SubmittedFile& earlier : priorTermFiles(priorDir)) files.push_back(std::move(earlier));
    std::vector<SimilarLabs> similar;
    for (const SimilarPair& pair : similarPairs(files, stubs, DefaultSimilarityThreshold))
        similar.push_back({pair.first, pair.second, pair.lab, pair.similarity});
    return similar;
}

} // namespace pathlab::grader
