// Hostile submission: looks for the instructor's secrets and the host's paths wherever a process
// may read them (the first process's and its own environment and command line, the mounts, the
// control groups, the descriptors it holds), prints what it found and aborts, so that the
// grader's feedback carries it out: PATHLAB_TEST_SECRET, an environment variable the test
// gives the grader; the host kernel's boot options and build; the kit's folder compiled into the
// programs. In the sandbox there is nothing to find: the first process is the grader's,
// unreadable, every file was copied in at a neutral path, the kernel's files read as nothing,
// and the programs name their sources from the kit's folder.
#include "pathlab/lab.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <dirent.h>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

namespace pathlab::branching {

namespace {

std::string contents(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return "";
    std::stringstream text;
    text << in.rdbuf();
    std::string s = text.str();
    for (char& c : s)
        if (c == '\0' || c == '\n') c = ' ';
    return s;
}

/// Every word of `text` that is a path outside what the sandbox is made of, or the secret.
std::string findings(const std::string& text) {
    std::istringstream words(text);
    std::string found;
    for (std::string word; words >> word;) {
        const bool secret = word.rfind("PATHLAB_TEST_SECRET=", 0) == 0;
        bool foreign = word.size() > 1 && word[0] == '/';
        for (const char* own : {"/usr", "/dev", "/proc", "/etc/", "/scratch", "/pathlab", "/scene",
                                "/lib", "/bin", "/newroot", "/sys", "/"})
            if (word == own || word.rfind(std::string(own) + "/", 0) == 0 ||
                (own[std::strlen(own) - 1] == '/' && word.rfind(own, 0) == 0))
                foreign = false;
        if (secret || foreign) found += " " + word;
    }
    return found;
}

} // namespace

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    std::string found;
    for (const char* file : {"/proc/1/environ", "/proc/self/environ", "/proc/1/cmdline",
                             "/proc/self/cmdline", "/proc/self/mountinfo", "/proc/1/mountinfo",
                             "/proc/self/cgroup", "/proc/sys/kernel/hostname"})
        found += findings(contents(file));
    // The host's kernel (its boot options and build) and the kit's folder on the host, compiled
    // into the programs the sandbox runs.
    for (const char* file : {"/proc/cmdline", "/proc/version"})
        if (!contents(file).empty()) found += std::string(" readable:") + file;
    for (const char* program : {"/pathlab/viewer", "/pathlab/init"})
        if (contents(program).find("@SOURCE@/") != std::string::npos)
            found += std::string(" host-path-in:") + program;
    if (DIR* fds = ::opendir("/proc/self/fd")) {
        while (const dirent* entry = ::readdir(fds)) {
            char target[512] = {};
            const std::string link = std::string("/proc/self/fd/") + entry->d_name;
            if (::readlink(link.c_str(), target, sizeof target - 1) > 0) found += findings(target);
        }
        ::closedir(fds);
    }
    std::printf("SNOOPED:%s\n", found.empty() ? " nothing" : found.c_str());
    std::fflush(stdout);
    std::abort();
    (void)ray, (void)depth, (void)ctx;
}

} // namespace pathlab::branching
