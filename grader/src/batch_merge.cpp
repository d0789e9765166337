// grader merge: the gradebooks of batch shards (grader batch --shard, run on several machines)
// as one.
#include "commands.h"
#include "gradebook.h"

#include "pathlab/input_error.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace pathlab::grader {

namespace fs = std::filesystem;

int mergeBatches(const Arguments& a) {
    fs::create_directories(a.out + "/submissions");
    std::vector<GradebookEntry> all;
    for (const std::string& shard : a.inputs) {
        const fs::path folder = fs::path(shard) / "submissions";
        if (!fs::is_directory(folder)) throw InputError(shard + ": not a batch's output (no submissions/ in it)");
        for (const auto& entry : fs::directory_iterator(folder)) {
            const std::string id = entry.path().filename().string();
            const GradebookEntry e = readGradebookEntry(shard, id, "");
            if (std::any_of(all.begin(), all.end(), [&](const GradebookEntry& x) { return x.id == id; }))
                throw InputError("submission '" + id + "' is in more than one shard");
            if (fs::absolute(shard) != fs::absolute(a.out))
                fs::copy(entry.path(), fs::path(a.out) / "submissions" / id,
                         fs::copy_options::recursive | fs::copy_options::overwrite_existing);
            all.push_back(e);
        }
    }
    std::sort(all.begin(), all.end(), [](const GradebookEntry& x, const GradebookEntry& y) { return x.id < y.id; });
    writeGradebook(a.out, all);
    std::printf("merged %zu submission(s) from %zu shard(s): %s/gradebook.csv\n", all.size(),
                a.inputs.size(), a.out.c_str());
    return 0;
}

} // namespace pathlab::grader
