#pragma once
/// One grading per output folder: two batches (or a batch started again while the first still
/// runs) writing one folder would overwrite each other's files and read each other's halves.

#include <string>

namespace pathlab::grader {

/// An exclusive lock on FOLDER/.lock, held while this object lives (and released by the kernel
/// if the process dies). The lock file names the process that holds it, so that a second
/// grading refuses in one line naming the first.
class OutputLock {
public:
    /// Takes the lock, or throws InputError: "FOLDER is being written by another `what`
    /// (process N, started at T): ...". Makes FOLDER if needed.
    OutputLock(const std::string& folder, const std::string& what);
    ~OutputLock();
    OutputLock(const OutputLock&) = delete;
    OutputLock& operator=(const OutputLock&) = delete;

private:
    int fd_ = -1;
};

} // namespace pathlab::grader
