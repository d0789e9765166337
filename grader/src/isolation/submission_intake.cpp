#include "isolation/submission_intake.h"

#include "common/plain_id.h"
#include "pathlab/render/lab_registry.h"

#include <nlohmann/json.hpp>

#include <ctime>
#include <filesystem>
#include <fstream>

namespace pathlab::grader {

namespace {

namespace fs = std::filesystem;

const std::string unpackScript = std::string(PATHLAB_GRADER_DIR) + "/sandbox/unpack_submission.py";

/// A time the submission tells of itself (seconds since 1970), if it could be one: after 2000
/// and no later than two days from now (a commit's clock may be off by a zone or so). Else 0,
/// unknown, and a problem naming it: the student's machine sets these, and a wild one (a date in
/// 2106, a negative one) must neither wrap around nor pass for on time.
long long plausibleTime(const nlohmann::json& when, const std::string& what,
                        std::vector<std::string>& problems) {
    if (when.is_null()) return 0;
    constexpr long long Year2000 = 946684800, TwoDays = 2 * 24 * 3600;
    const long long latest = static_cast<long long>(std::time(nullptr)) + TwoDays;
    // JSON reads a positive integer as unsigned: one past long long's range would wrap.
    long long at = -1;
    if (when.is_number_unsigned())
        at = when.get<unsigned long long>() > (1ULL << 40)
                 ? -1
                 : static_cast<long long>(when.get<unsigned long long>());
    else if (when.is_number_integer())
        at = when.get<long long>();
    if (at >= Year2000 && at <= latest) return at;
    problems.push_back(what + ", " + when.dump() +
                       " seconds since 1970, is not a time it could have been handed in: "
                       "no time is kept (give it with --times)");
    return 0;
}

bool endsWith(const std::string& text, const std::string& end) {
    return text.size() >= end.size() &&
           text.compare(text.size() - end.size(), end.size(), end) == 0;
}

/// The archive extension of a submission file ("" for a folder), as the unpacker reads it.
std::string archiveExtension(const std::string& path) {
    std::string lower = fs::path(path).filename().string();
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    for (const char* extension : {".tar.gz", ".tgz", ".tar", ".zip"})
        if (endsWith(lower, extension)) return extension;
    return "";
}

} // namespace

std::string submissionId(const std::string& submission) {
    std::string name = fs::path(submission).lexically_normal().filename().string();
    if (name.empty())
        name = fs::path(submission).lexically_normal().parent_path().filename().string();
    return plainId(name.substr(0, name.size() - archiveExtension(name).size()));
}

Intake takeSubmission(const std::string& submission, const std::string& folder,
                      const SandboxPolicy& policy) {
    Intake intake;
    std::error_code error;
    const fs::file_status status = fs::symlink_status(submission, error);
    if (error || !fs::exists(status)) {
        intake.problems.push_back(submission + ": no such file or folder");
        return intake;
    }
    if (fs::is_symlink(status)) {
        intake.problems.push_back(
            submission + ": a symbolic link; submissions are taken as they are, never followed");
        return intake;
    }
    const std::string inside = "/in/submission" + archiveExtension(submission);
    SandboxRun run;
    run.command = {"/usr/bin/python3", "/pathlab/unpack_submission.py", inside,
                   std::to_string(MaxLabFileBytes)};
    for (Lab lab : AllLabs) run.command.push_back(labFileName(lab));
    // Bound as it is, links and all, for the unpacker to refuse them; it is the kit's own code,
    // and nothing of the submission runs here (git reads its objects as data).
    run.bound = {{fs::absolute(submission).string(), inside}};
    run.files = {{unpackScript, "/pathlab/unpack_submission.py"}};
    for (Lab lab : AllLabs) run.collect.push_back(labFileName(lab));
    run.collect.push_back("intake.json");
    run.scratchBytes = 16LL << 20;
    const ProcessLimits limits{/*wallSeconds*/ 60, /*memoryBytes*/ 1LL << 30, /*cpuSeconds*/ 60,
                               /*fileBytes*/ 4LL << 20, /*processes*/ 16};
    const SandboxOutcome outcome = runInSandbox(run, limits, policy);
    const auto report = outcome.files.find("intake.json");
    if (!outcome.process.succeeded() || !outcome.problem.empty() || report == outcome.files.end()) {
        intake.problems.push_back(
            "the submission could not be read (" +
            (outcome.problem.empty() ? outcome.process.describe() : outcome.problem) +
            "): " + outcome.process.outputTail(2));
        return intake;
    }
    try {
        const nlohmann::json j = nlohmann::json::parse(report->second);
        intake.kind = j.at("kind");
        intake.problems = j.at("problems").get<std::vector<std::string>>();
        intake.commit = j.value("commit", "");
        if (j.contains("submitted_at"))
            intake.submittedAt = plausibleTime(j.at("submitted_at"), "its time", intake.problems);
        intake.timeSource = j.value("time_source", "");
        if (j.contains("lab_times") && j.at("lab_times").is_object())
            for (const auto& [name, when] : j.at("lab_times").items())
                if (const long long at = plausibleTime(when, name + "'s time", intake.problems))
                    intake.labTimes[name] = at;
        for (const auto& [name, where] : j.at("taken").items()) {
            const auto file = outcome.files.find(name);
            if (file == outcome.files.end() || file->second.size() > MaxLabFileBytes) continue;
            std::ofstream(folder + "/" + name, std::ios::binary) << file->second;
            fs::permissions(folder + "/" + name, fs::perms::owner_read | fs::perms::owner_write |
                                                     fs::perms::group_read |
                                                     fs::perms::others_read);
            intake.taken[name] = where.get<std::string>();
        }
    } catch (const nlohmann::json::exception& e) {
        intake.problems.push_back(std::string("the submission's report could not be read: ") +
                                  e.what());
    }
    return intake;
}

} // namespace pathlab::grader
