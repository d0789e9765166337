#pragma once
/// The lock that keeps the timed runs of concurrent gradings (grader batch's jobs, batches on one
/// machine) from running at once on the timing core: the frame-rate check's series, and the race
/// check's render, which needs two cores.

#include <fcntl.h>
#include <string>
#include <sys/file.h>
#include <unistd.h>

namespace pathlab::grader {

/// Holds an exclusive lock on a file while it lives (none for an empty path), so that the timed
/// series of concurrent gradings take turns. It waits at most `MaxWaitSeconds` for it: the file
/// is shared by every user of the machine, and a process that holds it for ever (another user's,
/// on a shared node) must not stop every batch; after that the runs go on unlocked, and
/// `waitedInVain` says so.
class TimingLock {
public:
    static constexpr int MaxWaitSeconds = 600;

    explicit TimingLock(const std::string& path) {
        if (path.empty()) return;
        // Shared by every batch on the machine, whoever runs it: a lock file another user made is
        // still locked through a read-only descriptor.
        fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
        if (fd_ < 0) fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
        if (fd_ < 0) return;
        for (int tenths = 0; ::flock(fd_, LOCK_EX | LOCK_NB) != 0; ++tenths) {
            if (tenths >= 10 * MaxWaitSeconds) {
                waitedInVain_ = true;
                ::close(fd_);
                fd_ = -1;
                return;
            }
            ::usleep(100000);
        }
    }
    ~TimingLock() {
        if (fd_ >= 0) ::close(fd_); // closing releases the lock
    }
    TimingLock(const TimingLock&) = delete;
    TimingLock& operator=(const TimingLock&) = delete;

    /// The lock was held by another process for MaxWaitSeconds: the runs went on without it.
    bool waitedInVain() const { return waitedInVain_; }

private:
    int fd_ = -1;
    bool waitedInVain_ = false;
};

} // namespace pathlab::grader
