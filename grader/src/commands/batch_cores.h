#pragma once
/// The cores of a batch, by what runs on them: the first core the grader may use is kept for
/// timed runs, taken by one grading at a time through a lock shared by every batch on the
/// machine; compiling and the correctness renders of every job share the others.

#include <string>
#include <vector>

namespace pathlab::grader {

/// The cores this process may use, in order.
std::vector<int> allowedCpus();
/// "0,2,3": the form --timing-cpus and --work-cpus take.
std::string joinCpus(const std::vector<int>& cpus);
/// One lock per timing core for the whole machine: batches on one machine (two shards on one
/// node, two classes) that time on the same core take turns, as the jobs of one batch do.
std::string timingLockFor(const std::vector<int>& timingCpus);

/// The cores of a batch, by what runs on them.
struct Cores {
    std::vector<int> timing, work;
};

/// The first core for timed runs, the rest for everything else.
Cores splitCores(const std::vector<int>& cpus);

} // namespace pathlab::grader
