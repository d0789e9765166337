// Linux only (process/CMakeLists.txt builds it there).
#include "process/seccomp_filter.h"

#include <cerrno>
#include <cstddef>
#include <cstring>
#include <linux/audit.h>
#include <linux/filter.h>
#include <linux/seccomp.h>
#include <sched.h>
#include <stdexcept>
#include <string>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace pathlab {

namespace {

#if defined(__x86_64__)
constexpr unsigned thisArchitecture = AUDIT_ARCH_X86_64;
#elif defined(__aarch64__)
constexpr unsigned thisArchitecture = AUDIT_ARCH_AARCH64;
#else
#error "installSeccompFilter: add this architecture's AUDIT_ARCH value"
#endif

constexpr unsigned errnoReturn(int error) { return SECCOMP_RET_ERRNO | (error & SECCOMP_RET_DATA); }

sock_filter load(unsigned offset) { return BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offset); }
sock_filter ret(unsigned value) { return BPF_STMT(BPF_RET | BPF_K, value); }
/// If the loaded value equals `value`, go on to the next instruction, else skip one.
sock_filter ifEqual(unsigned value) { return BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, value, 0, 1); }

} // namespace

void installSeccompFilter(const SeccompRules& rules) {
    std::vector<sock_filter> program = {
        load(offsetof(seccomp_data, arch)),
        BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, thisArchitecture, 1, 0),
        ret(SECCOMP_RET_KILL_PROCESS),
        load(offsetof(seccomp_data, nr)),
#if defined(__x86_64__)
        BPF_JUMP(BPF_JMP | BPF_JGE | BPF_K, 0x40000000u, 0, 1), // the x32 ABI
        ret(errnoReturn(EPERM)),
#endif
    };
    for (const RefusedCall& call : rules.calls) {
        program.push_back(ifEqual(static_cast<unsigned>(call.number)));
        program.push_back(ret(errnoReturn(call.error)));
    }
    if (rules.refuseNewProcesses) {
        program.insert(program.end(), {
                                          ifEqual(__NR_clone3),
                                          ret(errnoReturn(ENOSYS)),
                                          BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, __NR_clone, 0, 3),
                                          // the flags' low 32 bits (little-endian)
                                          load(offsetof(seccomp_data, args[0])),
                                          BPF_JUMP(BPF_JMP | BPF_JSET | BPF_K, CLONE_THREAD, 1, 0),
                                          ret(errnoReturn(EPERM)),
                                      });
    }
    program.push_back(ret(SECCOMP_RET_ALLOW));
    const sock_fprog filter{static_cast<unsigned short>(program.size()), program.data()};
    if (::prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0 ||
        ::syscall(SYS_seccomp, SECCOMP_SET_MODE_FILTER, SECCOMP_FILTER_FLAG_TSYNC, &filter) != 0)
        throw std::runtime_error(std::string("seccomp: ") + std::strerror(errno));
}

} // namespace pathlab
