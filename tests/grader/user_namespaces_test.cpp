// The grader's remedy when bubblewrap gets no user namespace: the setting that forbids it, read
// from a kernel settings folder made here, and the command that allows it.
#include "isolation/user_namespaces.h"

#include "catch.h"
#include "messages.h"
#include "test_support.h"

#include <filesystem>
#include <fstream>

namespace {

namespace fs = std::filesystem;

/// A /proc/sys with one setting in it.
std::string procSysWith(const std::string& name, const std::string& value) {
    const fs::path folder = pathlab::test::temporaryFolder("procsys");
    fs::create_directories((folder / name).parent_path());
    std::ofstream(folder / name) << value << "\n";
    return folder.string();
}

} // namespace

TEST_CASE("Ubuntu 24.04's AppArmor restriction is named with both of its remedies", "[sandbox]") {
    const std::string remedy = pathlab::grader::userNamespaceRemedy(
        procSysWith("kernel/apparmor_restrict_unprivileged_userns", "1"));
    CHECK(contains(remedy, "sysctl -w kernel.apparmor_restrict_unprivileged_userns=0"));
    CHECK(contains(remedy, "profile bwrap /usr/bin/bwrap"));
    CHECK(contains(remedy, "userns,"));
    CHECK(contains(remedy, "apparmor_parser -r /etc/apparmor.d/bwrap"));
}

TEST_CASE("Other switches that forbid user namespaces are named", "[sandbox]") {
    CHECK(contains(
        pathlab::grader::userNamespaceRemedy(procSysWith("kernel/unprivileged_userns_clone", "0")),
        "sysctl -w kernel.unprivileged_userns_clone=1"));
    CHECK(
        contains(pathlab::grader::userNamespaceRemedy(procSysWith("user/max_user_namespaces", "0")),
                 "sysctl -w user.max_user_namespaces="));
}

TEST_CASE("Settings that allow user namespaces need no remedy", "[sandbox]") {
    CHECK(pathlab::grader::userNamespaceRemedy(
              procSysWith("kernel/apparmor_restrict_unprivileged_userns", "0")) == "");
    CHECK(pathlab::grader::userNamespaceRemedy(
              procSysWith("kernel/unprivileged_userns_clone", "1")) == "");
    CHECK(pathlab::grader::userNamespaceRemedy("/nonexistent-proc-sys") == "");
}
