// Each lab file's own time as the intake finds it (isolation/submission_intake.h), for a late
// policy with a deadline per lab: in a git repository, the last commit that changed the file
// (not HEAD's); in a folder, the file's modification time. Linux with bubblewrap only, as the
// intake runs in the sandbox; where bubblewrap cannot make one, the test says so and checks
// nothing.
#include "catch.h"

#if PATHLAB_SANDBOX

#include "isolation/submission_intake.h"
#include "sandbox_here.h"
#include "test_support.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>

using namespace pathlab::grader;
namespace fs = std::filesystem;

namespace {

/// Readable by the sandbox's user, as a class's submissions are.
void readableBySandbox(const fs::path& folder) {
    fs::permissions(folder, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                                fs::perms::others_read | fs::perms::others_exec);
}

/// Runs `command` (a shell line), failing the test if it fails.
void shell(const std::string& command) { REQUIRE(std::system(command.c_str()) == 0); }

} // namespace

TEST_CASE("a lab's time is the last commit that changed its file, or its modification time",
          "[grader][sandbox]") {
    if (!sandboxHere()) return;
    const pathlab::test::ScratchFolder scratch("intake-times");
    readableBySandbox(scratch.path);
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

namespace {

bool mentions(const Intake& intake, const std::string& words) {
    for (const std::string& problem : intake.problems)
        if (problem.find(words) != std::string::npos) return true;
    return false;
}

} // namespace

TEST_CASE("a student's repository cannot pass a lab off as on time: a wild commit date, a HEAD "
          "that is no commit, borrowed objects; an honest shallow clone is dated by its own "
          "commits",
          "[grader][sandbox]") {
    if (!sandboxHere()) return;
    const pathlab::test::ScratchFolder scratch("intake-hostile");
    readableBySandbox(scratch.path);
    const SandboxPolicy policy{{}, sandboxUserForThisProcess()};
    int taken = 0;
    auto intakeOf = [&](const fs::path& submission) {
        const fs::path folder = scratch.path / ("taken-" + std::to_string(++taken));
        fs::create_directories(folder);
        return takeSubmission(submission.string(), folder.string(), policy);
    };
    auto repository = [&](const std::string& name) {
        const fs::path at = scratch.path / name;
        fs::create_directories(at / "labs");
        shell("git init -q '" + at.string() + "'");
        return at;
    };
    auto commit = [&](const fs::path& at, const std::string& file, const std::string& date) {
        std::ofstream(at / file) << "// " << date << "\n";
        const std::string git =
            "git -C '" + at.string() + "' -c user.name=s -c user.email=s@example.com";
        shell(git + " add -A && GIT_COMMITTER_DATE='" + date + "' " + git + " commit -q -m c");
    };

    // A lab committed in 2200 (which git takes): no time is kept, and the intake says why,
    // instead of a date that would wrap around into negative late days.
    const fs::path future = repository("future");
    commit(future, "labs/uniform.cpp", "@7258118400 +0000");
    const Intake wild = intakeOf(future);
    CHECK(wild.submittedAt == 0);
    CHECK(wild.labTimes.count("uniform.cpp") == 0);
    CHECK(mentions(wild, "is not a time it could have been handed in"));

    // HEAD naming a tree: its files are not taken, for want of a commit and its time.
    const fs::path tree = repository("tree");
    commit(tree, "labs/uniform.cpp", "2026-10-08T12:00:00Z");
    shell("git -C '" + tree.string() + "' rev-parse 'HEAD^{tree}' > '" +
          (tree / ".git/HEAD").string() + ".new' && mv '" + (tree / ".git/HEAD").string() +
          ".new' '" + (tree / ".git/HEAD").string() + "'");
    const Intake noCommit = intakeOf(tree);
    CHECK(noCommit.taken.empty());
    CHECK(mentions(noCommit, "which is not a commit"));

    // Objects borrowed from elsewhere (objects/info/alternates): refused.
    const fs::path borrowing = repository("borrowing");
    commit(borrowing, "labs/uniform.cpp", "2026-10-08T12:00:00Z");
    std::ofstream(borrowing / ".git/objects/info/alternates") << "/elsewhere/objects\n";
    CHECK(mentions(intakeOf(borrowing), "objects/info/alternates"));

    // An honest shallow clone: branching last changed before its depth, uniform within it.
    const fs::path full = repository("full");
    commit(full, "labs/branching.cpp", "2026-10-01T12:00:00Z");
    commit(full, "labs/uniform.cpp", "2026-10-08T12:00:00Z");
    commit(full, "README", "2026-11-20T12:00:00Z");
    const fs::path shallow = scratch.path / "shallow";
    shell("git clone -q --depth 2 'file://" + full.string() + "' '" + shallow.string() + "'");
    const Intake fromShallow = intakeOf(shallow);
    CHECK(fromShallow.labTimes.at("uniform.cpp") == 1791460800LL); // its own commit
    // branching is older than the clone's history: dated by its first commit there, uniform's.
    CHECK(fromShallow.labTimes.at("branching.cpp") == 1791460800LL);
}

#endif
