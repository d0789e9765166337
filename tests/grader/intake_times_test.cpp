// Each lab file's own time as the intake finds it (isolation/submission_intake.h), for a late
// policy with a deadline per lab: in a git repository, the last commit that changed the file
// (not HEAD's); in a folder, the file's modification time. Linux with bubblewrap only, as the
// intake runs in the sandbox; where bubblewrap cannot make one, the test says so and checks
// nothing.
#include "catch.h"

#if PATHLAB_SANDBOX

#include "isolation/submission_intake.h"
#include "test_support.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>

using namespace pathlab::grader;
namespace fs = std::filesystem;

namespace {

bool sandboxHere() {
    static const std::string reason = sandboxUnavailableReason();
    if (!reason.empty()) WARN("no sandbox here, nothing checked: " << reason);
    return reason.empty();
}

/// Runs `command` (a shell line), failing the test if it fails.
void shell(const std::string& command) { REQUIRE(std::system(command.c_str()) == 0); }

} // namespace

TEST_CASE("a lab's time is the last commit that changed its file, or its modification time",
          "[grader][sandbox]") {
    if (!sandboxHere()) return;
    const pathlab::test::ScratchFolder scratch("intake-times");
    // Readable by the sandbox's user, as a class's submissions are.
    fs::permissions(scratch.path, fs::perms::owner_all | fs::perms::group_read |
                                      fs::perms::group_exec | fs::perms::others_read |
                                      fs::perms::others_exec);
    const fs::path repository = scratch.path / "dan";
    fs::create_directories(repository / "labs");
    const std::string git =
        "git -C '" + repository.string() + "' -c user.name=s -c user.email=s@example.com";
    // branching.cpp committed on 2026-10-01, uniform.cpp on 2026-10-08, then a README on
    // 2026-11-20: HEAD's time is the README's, each lab's its own commit's.
    shell("git init -q '" + repository.string() + "'");
    std::ofstream(repository / "labs/branching.cpp") << "// branching\n";
    shell(git + " add -A && GIT_COMMITTER_DATE=2026-10-01T12:00:00Z " + git + " commit -q -m one");
    std::ofstream(repository / "labs/uniform.cpp") << "// uniform\n";
    shell(git + " add -A && GIT_COMMITTER_DATE=2026-10-08T12:00:00Z " + git + " commit -q -m two");
    std::ofstream(repository / "README") << "notes\n";
    shell(git + " add -A && GIT_COMMITTER_DATE=2026-11-20T12:00:00Z " + git +
          " commit -q -m three");
    const SandboxPolicy policy{{}, sandboxUserForThisProcess()};
    fs::create_directories(scratch.path / "taken-git");
    const Intake fromGit =
        takeSubmission(repository.string(), (scratch.path / "taken-git").string(), policy);
    INFO(fromGit.problems.size());
    CHECK(fromGit.submittedAt == 1795176000LL);                  // 2026-11-20T12:00:00Z
    CHECK(fromGit.labTimes.at("branching.cpp") == 1790856000LL); // 2026-10-01T12:00:00Z
    CHECK(fromGit.labTimes.at("uniform.cpp") == 1791460800LL);   // 2026-10-08T12:00:00Z

    // A folder: each file's modification time.
    const fs::path folder = scratch.path / "eve";
    fs::create_directories(folder);
    std::ofstream(folder / "branching.cpp") << "// branching\n";
    std::ofstream(folder / "uniform.cpp") << "// uniform\n";
    shell("touch -d 2026-10-01T12:00:00Z '" + (folder / "branching.cpp").string() + "'");
    shell("touch -d 2026-10-08T12:00:00Z '" + (folder / "uniform.cpp").string() + "'");
    fs::create_directories(scratch.path / "taken-folder");
    const Intake fromFolder =
        takeSubmission(folder.string(), (scratch.path / "taken-folder").string(), policy);
    CHECK(fromFolder.submittedAt == 1791460800LL);
    CHECK(fromFolder.labTimes.at("branching.cpp") == 1790856000LL);
    CHECK(fromFolder.labTimes.at("uniform.cpp") == 1791460800LL);
}

#endif
