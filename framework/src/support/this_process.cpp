#include "pathlab/support/this_process.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

#if defined(_WIN32)
#include <io.h>
#include <windows.h>
#else
#include <dlfcn.h>
#include <unistd.h>
#endif
#if defined(__APPLE__)
#include <mach-o/dyld.h>
#include <sys/sysctl.h>
#endif

namespace pathlab {

namespace fs = std::filesystem;

fs::path thisProgram() {
#if defined(_WIN32)
    std::wstring name(MAX_PATH, L'\0');
    DWORD length = 0;
    while ((length = ::GetModuleFileNameW(nullptr, name.data(), static_cast<DWORD>(name.size()))) ==
           name.size())
        name.resize(name.size() * 2);
    name.resize(length);
    return fs::path(name);
#elif defined(__APPLE__)
    uint32_t size = 0;
    ::_NSGetExecutablePath(nullptr, &size);
    std::string name(size, '\0');
    if (::_NSGetExecutablePath(name.data(), &size) != 0)
        throw std::runtime_error("cannot find this program's own file");
    return fs::canonical(name.c_str());
#else
    return fs::read_symlink("/proc/self/exe");
#endif
}

long processId() {
#if defined(_WIN32)
    return static_cast<long>(::GetCurrentProcessId());
#else
    return static_cast<long>(::getpid());
#endif
}

void* findLibrarySymbol(const fs::path& library, const char* symbol, std::string& why) {
#if defined(_WIN32)
    HMODULE handle = ::LoadLibraryW(library.c_str());
    if (!handle) {
        why = std::system_category().message(static_cast<int>(::GetLastError()));
        return nullptr;
    }
    void* address = reinterpret_cast<void*>(::GetProcAddress(handle, symbol));
    if (!address) why = std::string("no ") + symbol + " in it";
    return address;
#else
    void* handle = ::dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
        why = ::dlerror();
        return nullptr;
    }
    void* address = ::dlsym(handle, symbol);
    if (!address) why = std::string("no ") + symbol + " in it";
    return address;
#endif
}

bool standardErrorIsTerminal() {
#if defined(_WIN32)
    return ::_isatty(::_fileno(stderr)) != 0;
#else
    return ::isatty(STDERR_FILENO) != 0;
#endif
}

bool debuggerAttached() {
#if defined(_WIN32)
    return ::IsDebuggerPresent() != 0;
#elif defined(__APPLE__)
    int query[] = {CTL_KERN, KERN_PROC, KERN_PROC_PID, ::getpid()};
    struct kinfo_proc info = {};
    size_t size = sizeof info;
    if (::sysctl(query, 4, &info, &size, nullptr, 0) != 0) return false;
    return (info.kp_proc.p_flag & P_TRACED) != 0;
#else
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);)
        if (line.rfind("TracerPid:", 0) == 0)
            return std::strtol(line.c_str() + 10, nullptr, 10) != 0;
    return false;
#endif
}

} // namespace pathlab
