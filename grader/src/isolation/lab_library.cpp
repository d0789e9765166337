#include "isolation/lab_library.h"

#include "pathlab/support/input_error.h"
#include "pathlab/support/printable_text.h"
#include "pathlab/support/whole_file.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace pathlab::grader {

namespace {

namespace fs = std::filesystem;

// What one compiler or linker run may use. A lab file compiles in a second or two; the limits
// stop a compiler bomb (templates or macros that expand without end) or an #include of a device.
const ProcessLimits compileLimits{/*wallSeconds*/ 60, /*memoryBytes*/ 2LL << 30,
                                  /*cpuSeconds*/ 60, /*fileBytes*/ 64LL << 20, /*processes*/ 16};

void writeFile(const std::string& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary);
    out << bytes;
    if (!out) throw std::runtime_error(path + ": cannot write");
    fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read |
                              fs::perms::others_read);
}

/// The compiler's first lines, with the sandbox's folder names taken out.
std::string compilerMessages(const ProcessOutcome& outcome) {
    std::istringstream in(outcome.output);
    std::string line, text;
    for (int n = 0; n < 25 && std::getline(in, line); ++n) {
        for (const std::string folder :
             {"/submission/", "/pathlab/include/", "/pathlab/generated/", "/pathlab/runner/"})
            for (size_t at; (at = line.find(folder)) != std::string::npos;)
                line.erase(at, folder.size());
        // The messages quote the submission's own bytes (an #error line may hold any): no
        // control byte of them reaches a log, a terminal or a page.
        text += printableText(line) + "\n";
    }
    return text;
}

/// Why a compiler run failed, in words, or "" if it succeeded.
std::string compileFailure(const SandboxOutcome& o, const std::string& what) {
    const ProcessOutcome& p = o.process;
    if (p.timedOut)
        return what + ": the compiler did not finish within 60 s (a compiler bomb, or an "
                      "#include of a device?)";
    if (p.signal != 0) return what + ": the compiler " + p.describe();
    if (!p.succeeded()) return what + " does not compile:\n" + compilerMessages(p);
    if (!o.problem.empty()) return what + ": " + o.problem;
    return "";
}

/// Compiles `source` (a host path) as the labs of `implementation` into `object`, with the
/// build's flags and `extraFlags`.
std::string compileObject(const LabBuild& build, const std::string& source,
                          const std::string& implementation, const std::string& object,
                          const SandboxPolicy& policy,
                          const std::vector<std::string>& extraFlags = {}) {
    const std::string name = fs::path(source).filename().string();
    SandboxRun run;
    run.command = {build.compiler};
    run.command.insert(run.command.end(), build.flags.begin(), build.flags.end());
    run.command.insert(run.command.end(), extraFlags.begin(), extraFlags.end());
    run.command.insert(run.command.end(), {"-DPATHLAB_IMPL=" + implementation, "-I/pathlab/include",
                                           "-I/pathlab/generated"});
    // The table alone sees the runner's headers; a lab file sees the student API (lab.h).
    if (source == build.labTable) run.command.push_back("-I/pathlab/runner");
    // Each lab's namespace named after the set, as CMakeLists.txt's pathlab_lab_library does.
    for (Lab lab : AllLabs)
        run.command.push_back("-D" + std::string(labName(lab)) + "=" + std::string(labName(lab)) +
                              "_" + implementation);
    run.command.insert(run.command.end(), {"-c", "/submission/" + name, "-o", "out.o"});
    run.files = {{build.include, "/pathlab/include"},
                 {build.generatedInclude, "/pathlab/generated"},
                 {build.runnerInclude, "/pathlab/runner"},
                 {source, "/submission/" + name}};
    run.collect = {"out.o"};
    run.scratchBytes = 128LL << 20;
    const SandboxOutcome outcome = runInSandbox(run, compileLimits, policy);
    const std::string failure = compileFailure(outcome, name);
    if (!failure.empty()) return failure;
    const auto file = outcome.files.find("out.o");
    if (file == outcome.files.end()) return name + ": the compiler wrote no object file";
    writeFile(object, file->second);
    return "";
}

/// Links `objects` into the shared library `library`, with `extraFlags`.
std::string linkLibrary(const LabBuild& build, const std::vector<std::string>& objects,
                        const std::string& library, const SandboxPolicy& policy,
                        const std::vector<std::string>& extraFlags = {}) {
    SandboxRun run;
    run.command = {build.compiler, "-shared", "-o", "labs.so"};
    run.command.insert(run.command.end(), extraFlags.begin(), extraFlags.end());
    for (size_t i = 0; i < objects.size(); ++i) {
        const std::string inside = "/objects/" + std::to_string(i) + ".o";
        run.files.push_back({objects[i], inside});
        run.command.push_back(inside);
    }
    run.collect = {"labs.so"};
    run.scratchBytes = 128LL << 20;
    const SandboxOutcome outcome = runInSandbox(run, compileLimits, policy);
    const std::string failure = compileFailure(outcome, "linking the labs");
    if (!failure.empty()) return failure;
    const auto file = outcome.files.find("labs.so");
    if (file == outcome.files.end()) return "the linker wrote no library";
    writeFile(library, file->second);
    return "";
}

/// Where a kit's parts live in its folder.
LabKit existingLabKitPaths(const std::string& folder) {
    LabKit kit;
    kit.folder = folder;
    kit.tableObject = folder + "/table.o";
    for (Lab lab : AllLabs)
        kit.stubObjects[lab] = folder + "/stub_" + std::string(labName(lab)) + ".o";
    kit.solutionsLibrary = folder + "/solutions.so";
    return kit;
}

} // namespace

LabBuild loadLabBuild(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw InputError(path + ": missing (it is written when PathLab is configured)");
    try {
        const nlohmann::json j = nlohmann::json::parse(in);
        return {j.at("compiler"),
                j.at("flags").get<std::vector<std::string>>(),
                j.at("include"),
                j.at("generated_include"),
                j.at("runner_include"),
                j.at("lab_table"),
                j.at("stubs"),
                j.at("solutions"),
                j.at("viewer"),
                j.value("race_check_viewer", ""),
                j.value("race_check_flags", std::vector<std::string>{})};
    } catch (const nlohmann::json::exception& e) {
        throw InputError(path + ": " + e.what());
    }
}

LabKit existingLabKit(const std::string& folder) {
    const LabKit kit = existingLabKitPaths(folder);
    std::vector<std::string> parts = {kit.tableObject, kit.solutionsLibrary};
    parts.insert(parts.end(), kit.stubObjects.begin(), kit.stubObjects.end());
    for (const std::string& part : parts)
        if (!fs::exists(part)) throw InputError("the lab kit in " + folder + " lacks " + part);
    return kit;
}

/// What a kit is made from: the compiler, its flags and every source and header, so that a kit
/// already built from the same is reused (a restarted batch, a second shard on one machine).
std::string kitFingerprint(const LabBuild& build) {
    std::string text = build.compiler;
    for (const std::string& flag : build.flags) text += " " + flag;
    std::vector<std::string> files = {build.labTable};
    for (Lab lab : AllLabs)
        files.insert(files.end(), {build.stubs + "/" + labFileName(lab),
                                   build.solutions + "/" + labFileName(lab)});
    for (const std::string& folder : {build.include, build.generatedInclude, build.runnerInclude})
        for (const auto& entry : fs::recursive_directory_iterator(folder))
            if (entry.is_regular_file()) files.push_back(entry.path().string());
    std::sort(files.begin(), files.end());
    for (const std::string& file : files) text += "\n" + file + "\n" + readFile(file);
    return std::to_string(std::hash<std::string>{}(text));
}

LabKit buildLabKit(const LabBuild& build, const std::string& folder, const SandboxPolicy& policy) {
    const std::string fingerprint = kitFingerprint(build);
    const std::string fingerprintFile = folder + "/fingerprint";
    if (std::ifstream in(fingerprintFile); in) {
        std::string made;
        std::getline(in, made);
        try {
            if (made == fingerprint) return existingLabKit(folder);
        } catch (const InputError&) {
            // A part is missing: build it all again.
        }
    }
    fs::remove(fingerprintFile);
    fs::create_directories(folder);
    fs::permissions(folder, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                                fs::perms::others_read | fs::perms::others_exec);
    LabKit kit = existingLabKitPaths(folder);
    auto compile = [&](const std::string& source, const std::string& implementation,
                       const std::string& object) {
        const std::string failure = compileObject(build, source, implementation, object, policy);
        if (!failure.empty()) throw std::runtime_error("PathLab's own " + failure);
    };
    compile(build.labTable, "student", kit.tableObject);
    std::vector<std::string> solutionObjects;
    for (Lab lab : AllLabs) {
        compile(build.stubs + "/" + labFileName(lab), "student", kit.stubObjects[lab]);
        solutionObjects.push_back(folder + "/solution_" + std::string(labName(lab)) + ".o");
        compile(build.solutions + "/" + labFileName(lab), "student", solutionObjects.back());
    }
    solutionObjects.push_back(kit.tableObject);
    const std::string failure = linkLibrary(build, solutionObjects, kit.solutionsLibrary, policy);
    if (!failure.empty()) throw std::runtime_error("the reference solutions: " + failure);
    writeFile(fingerprintFile, fingerprint + "\n");
    return kit;
}

namespace {

/// The parts of lab `lab`'s library: its object, the table, and the stubs for the other labs.
std::vector<std::string> libraryParts(const LabKit& kit, Lab lab, const std::string& object) {
    std::vector<std::string> parts = {object, kit.tableObject};
    for (Lab other : AllLabs)
        if (other != lab) parts.push_back(kit.stubObjects[other]);
    return parts;
}

} // namespace

SubmissionLibrary buildSubmissionLibrary(const LabBuild& build, const LabKit& kit,
                                         const std::string& sources, const std::string& folder,
                                         const SandboxPolicy& policy) {
    SubmissionLibrary result;
    auto objectOf = [&](Lab lab) { return folder + "/" + std::string(labName(lab)) + ".o"; };
    for (Lab lab : AllLabs) {
        const std::string source = sources + "/" + labFileName(lab);
        LabCompilation& compiled = result.labs[lab];
        if (!fs::exists(source)) continue; // NotSubmitted
        compiled.messages = compileObject(build, source, "student", objectOf(lab), policy);
        compiled.status = compiled.messages.empty() ? LabCompilation::Status::Compiled
                                                    : LabCompilation::Status::Failed;
    }
    for (Lab lab : AllLabs) {
        if (result.labs[lab].status != LabCompilation::Status::Compiled) continue;
        // This lab's object; the stubs, which load and run nothing, for the others.
        const std::string library = folder + "/labs-" + std::string(labName(lab)) + ".so";
        result.problem[lab] =
            linkLibrary(build, libraryParts(kit, lab, objectOf(lab)), library, policy);
        if (result.problem[lab].empty()) result.library[lab] = library;
    }
    return result;
}

std::string buildRaceCheckLibrary(const LabBuild& build, const LabKit& kit, Lab lab,
                                  const std::string& sources, const std::string& folder,
                                  const SandboxPolicy& policy, std::string& library) {
    const std::string stem = folder + "/" + std::string(labName(lab)) + "-tsan";
    std::string failure = compileObject(build, sources + "/" + labFileName(lab), "student",
                                        stem + ".o", policy, build.raceCheckFlags);
    if (failure.empty())
        failure = linkLibrary(build, libraryParts(kit, lab, stem + ".o"), stem + ".so", policy,
                              build.raceCheckFlags);
    if (failure.empty()) library = stem + ".so";
    return failure;
}

} // namespace pathlab::grader
