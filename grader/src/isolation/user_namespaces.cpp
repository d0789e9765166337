#include "isolation/user_namespaces.h"

#include <fstream>

namespace pathlab::grader {

namespace {

/// A kernel setting's value, "" when the kernel has no such setting.
std::string setting(const std::string& procSys, const std::string& name) {
    std::ifstream in(procSys + "/" + name);
    std::string value;
    in >> value;
    return value;
}

} // namespace

std::string userNamespaceRemedy(const std::string& procSys) {
    // Ubuntu 23.10 and later (24.04 included): AppArmor lets only programs with a profile that
    // allows it make user namespaces, and Ubuntu ships no profile for bwrap.
    if (setting(procSys, "kernel/apparmor_restrict_unprivileged_userns") == "1")
        return "Ubuntu's AppArmor restricts unprivileged user namespaces "
               "(kernel.apparmor_restrict_unprivileged_userns = 1). Either allow them: "
               "sudo sysctl -w kernel.apparmor_restrict_unprivileged_userns=0 (until the next "
               "boot; a line in /etc/sysctl.d/60-pathlab.conf keeps it), or give bwrap an "
               "AppArmor profile that allows them: write /etc/apparmor.d/bwrap with the lines "
               "'abi <abi/4.0>,' 'include <tunables/global>' "
               "'profile bwrap /usr/bin/bwrap flags=(unconfined) { userns, }' and run "
               "sudo apparmor_parser -r /etc/apparmor.d/bwrap";
    // Debian before 11, and kernels built with Debian's patch: off by this switch.
    if (setting(procSys, "kernel/unprivileged_userns_clone") == "0")
        return "unprivileged user namespaces are off (kernel.unprivileged_userns_clone = 0): "
               "sudo sysctl -w kernel.unprivileged_userns_clone=1";
    if (setting(procSys, "user/max_user_namespaces") == "0")
        return "user namespaces are off (user.max_user_namespaces = 0): "
               "sudo sysctl -w user.max_user_namespaces=15000";
    return "";
}

} // namespace pathlab::grader
