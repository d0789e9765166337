#pragma once
/// Taking a submission in: only the allow-listed lab files, copied into a clean folder. The
/// submission (a folder, a .zip, a .tar.gz or a git repository) is read inside the sandbox, by
/// grader/sandbox/unpack_submission.py, so a hostile archive can do no harm here.

#include "isolation/sandbox.h"

#include <map>
#include <string>
#include <vector>

namespace pathlab::grader {

/// Lab files larger than this are refused: a lab is a few kilobytes.
constexpr long long MaxLabFileBytes = 256 << 10;

struct Intake {
    std::string kind;                         ///< "folder", "zip", "tar", "git repository (HEAD)"
    std::map<std::string, std::string> taken; ///< lab file name -> where it was in the submission
    std::vector<std::string> problems;        ///< skipped files and why, in words
    std::string commit;                       ///< a repository's HEAD commit ("" otherwise)
    /// When it was submitted as far as the submission tells (seconds since 1970; 0 unknown) and
    /// from what: "last commit", "lab files' modification time", "archive's modification time".
    long long submittedAt = 0;
    std::string timeSource;
    /// Each lab file's own time (lab file name -> seconds since 1970), for a late policy with a
    /// deadline per lab: the last commit that changed it, its modification time, or the archive's.
    std::map<std::string, long long> labTimes;
};

/// Copies the lab files of `submission` into `folder` (which must exist and be empty).
Intake takeSubmission(const std::string& submission, const std::string& folder,
                      const SandboxPolicy& policy);

/// A name for a submission in the gradebook: its file or folder name without the archive
/// extension, reduced to letters, digits, '.', '_' and '-'.
std::string submissionId(const std::string& submission);

} // namespace pathlab::grader
