#include "similarity/prior_terms.h"

#include "pathlab/render/lab_registry.h"
#include "pathlab/support/input_error.h"
#include "pathlab/support/whole_file.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>

namespace pathlab::grader {

namespace fs = std::filesystem;

int keepPriorTerm(const std::string& out, const std::vector<std::string>& ids,
                  const std::string& term, const std::string& dir) {
    if (term.empty() || term.find_first_of("/\\") != std::string::npos || term[0] == '.')
        throw InputError("option --term: '" + term + "' is not a plain name, like 2026-fall");
    nlohmann::json labs = nlohmann::json::object();
    int kept = 0;
    for (Lab lab : AllLabs) {
        nlohmann::json files = nlohmann::json::array();
        for (const std::string& id : ids) {
            const fs::path file =
                fs::path(out) / "submissions" / id / "submitted" / labFileName(lab);
            if (!fs::is_regular_file(file)) continue;
            files.push_back({{"id", id}, {"tokens", normalisedTokens(readFile(file.string()))}});
            ++kept;
        }
        labs[std::string(labName(lab))] = files;
    }
    fs::create_directories(dir);
    writeFileAtomically(dir + "/" + term + ".json",
                        nlohmann::json{{"term", term}, {"labs", labs}}.dump() + "\n");
    return kept;
}

std::vector<SubmittedFile> priorTermFiles(const std::string& dir) {
    if (!fs::is_directory(dir)) throw InputError("option --prior: '" + dir + "' is not a folder");
    std::vector<fs::path> terms;
    for (const auto& entry : fs::directory_iterator(dir))
        if (entry.path().extension() == ".json") terms.push_back(entry.path());
    std::sort(terms.begin(), terms.end());
    std::vector<SubmittedFile> files;
    for (const fs::path& path : terms) {
        try {
            const nlohmann::json j = nlohmann::json::parse(readFile(path.string()));
            const std::string term = j.at("term");
            for (const auto& [lab, kept] : j.at("labs").items())
                for (const nlohmann::json& file : kept)
                    files.emplace_back(term + "/" + file.at("id").get<std::string>(), lab,
                                       file.at("tokens").get<std::vector<std::string>>());
        } catch (const nlohmann::json::exception& e) {
            throw InputError(path.string() + ": not an earlier term kept by grader keep-term (" +
                             e.what() + ")");
        }
    }
    return files;
}

bool isPriorSubmission(const std::string& id) { return id.find('/') != std::string::npos; }

} // namespace pathlab::grader
