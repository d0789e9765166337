#pragma once
/// The running process: its program file, its id, the shared libraries it loads at run time
/// (the image plug-in, a submission's labs), whether a person watches its standard error and
/// whether a debugger holds it. The parts that differ between Linux, macOS and
/// Windows, in one place (this_process.cpp).

#include <filesystem>
#include <string>

/// Marks the one function a shared library of PathLab's exports (built with hidden symbols).
#if defined(_WIN32)
#define PATHLAB_EXPORT __declspec(dllexport)
#else
#define PATHLAB_EXPORT __attribute__((visibility("default")))
#endif

namespace pathlab {

/// This program's executable file (Linux: /proc/self/exe; macOS: _NSGetExecutablePath;
/// Windows: GetModuleFileNameW).
std::filesystem::path thisProgram();

/// This process's id, e.g. to name a temporary file no other process writes.
long processId();

/// The address of `symbol` in the shared library `library`, which stays loaded; nullptr, with
/// the system's reason in `why`, when the library or the symbol cannot be found.
void* findLibrarySymbol(const std::filesystem::path& library, const char* symbol, std::string& why);

/// Whether standard error is a terminal, where a line redrawn in place is seen, rather than a
/// pipe or a file, where it would only fill a log.
bool standardErrorIsTerminal();

/// Whether a debugger is attached (Linux: TracerPid in /proc/self/status; macOS: P_TRACED;
/// Windows: IsDebuggerPresent). False where that cannot be told.
bool debuggerAttached();

} // namespace pathlab
