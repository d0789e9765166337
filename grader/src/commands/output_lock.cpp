// POSIX (flock): Linux and macOS.
#include "commands/output_lock.h"

#include "common/local_time.h"

#include "pathlab/support/input_error.h"

#include <cerrno>
#include <cstring>
#include <ctime>
#include <fcntl.h>
#include <filesystem>
#include <string>
#include <sys/file.h>
#include <unistd.h>

namespace pathlab::grader {

OutputLock::OutputLock(const std::string& folder, const std::string& what) {
    std::filesystem::create_directories(folder);
    const std::string path = folder + "/.lock";
    // Close-on-exec: the gradings a batch starts must not hold its lock after it is gone.
    fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0)
        throw InputError(path + ": cannot open the output folder's lock: " + std::strerror(errno));
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
        char holder[256] = {};
        const ssize_t n = ::pread(fd_, holder, sizeof holder - 1, 0);
        std::string who = n > 0 ? std::string(holder, static_cast<size_t>(n)) : "";
        while (!who.empty() && (who.back() == '\n' || who.back() == ' ')) who.pop_back();
        ::close(fd_);
        fd_ = -1;
        throw InputError(folder + " is being written by another " + what + " (" +
                         (who.empty() ? "a process that has not said which" : who) +
                         "): wait until it ends, or write into another folder");
    }
    const std::string holder =
        "process " + std::to_string(::getpid()) + ", started at " + localTimeNow() + "\n";
    if (::ftruncate(fd_, 0) != 0 ||
        ::pwrite(fd_, holder.data(), holder.size(), 0) != static_cast<ssize_t>(holder.size()))
        throw InputError(path + ": cannot write the output folder's lock");
}

OutputLock::~OutputLock() {
    if (fd_ >= 0) ::close(fd_);
}

} // namespace pathlab::grader
