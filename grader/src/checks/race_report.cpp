#include "checks/race_report.h"

#include <cctype>
#include <sstream>

namespace pathlab::grader {

namespace {

/// Each report's text, from one "WARNING: ThreadSanitizer:" to the next.
std::vector<std::string> reports(const std::string& output) {
    const std::string start = "WARNING: ThreadSanitizer:";
    std::vector<std::string> found;
    for (size_t at = output.find(start); at != std::string::npos;) {
        const size_t next = output.find(start, at + start.size());
        found.push_back(output.substr(at, next == std::string::npos ? next : next - at));
        at = next;
    }
    return found;
}

/// The line number after `file` + ":" at `at` in `text`, or "" if there is none.
std::string lineNumberAt(const std::string& text, size_t at) {
    std::string digits;
    while (at < text.size() && std::isdigit(static_cast<unsigned char>(text[at])))
        digits += text[at++];
    return digits;
}

/// The last component of a qualified C++ name, outside any parentheses or template arguments:
/// "counter" of "pathlab::uniform_student::pathTrace(pathlab::Ray const&)::counter".
std::string unqualified(const std::string& name) {
    int depth = 0;
    for (size_t i = name.size(); i-- > 0;) {
        const char c = name[i];
        if (c == ')' || c == '>') ++depth;
        if (c == '(' || c == '<') --depth;
        if (depth == 0 && c == ':' && i > 0 && name[i - 1] == ':') return name.substr(i + 1);
    }
    return name;
}

} // namespace

std::string LabRace::text() const {
    std::string memory = "on memory shared by the threads";
    if (!variable.empty())
        memory = "on `" + variable + "` (a static or global variable shared by the threads)";
    else if (heap)
        memory = "on heap memory shared by the threads (its pointer kept in a static or global?)";
    return line + ": data race between render threads " + memory +
           ": keep per-sample state in local variables; render threads share nothing but ctx's "
           "read-only data";
}

std::vector<LabRace> labRaces(const std::string& output, const std::string& fileInside,
                              const std::string& fileShown) {
    std::vector<LabRace> races;
    for (const std::string& report : reports(output)) {
        if (report.rfind("WARNING: ThreadSanitizer: data race", 0) != 0) continue;
        // The first frame in the lab's file: the racing access itself, or the lab's call into a
        // header that made it.
        const std::string needle = fileInside + ":";
        const size_t frame = report.find(needle);
        if (frame == std::string::npos) continue;
        const std::string lineNumber = lineNumberAt(report, frame + needle.size());
        if (lineNumber.empty()) continue;
        LabRace race;
        race.line = fileShown + ":" + lineNumber;
        std::istringstream lines(report);
        for (std::string line; std::getline(lines, line);) {
            const std::string global = "Location is global '";
            if (const size_t at = line.find(global); at != std::string::npos) {
                const size_t end = line.find('\'', at + global.size());
                race.variable =
                    unqualified(line.substr(at + global.size(), end - at - global.size()));
            }
            if (line.find("Location is heap block") != std::string::npos) race.heap = true;
        }
        bool seen = false;
        for (const LabRace& r : races)
            seen = seen || (r.line == race.line && r.variable == race.variable);
        if (!seen) races.push_back(race);
    }
    return races;
}

} // namespace pathlab::grader
