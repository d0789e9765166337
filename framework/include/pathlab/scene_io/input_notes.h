#pragma once
/// The warnings and notes about a scene's files, gathered while they are read and printed once
/// they all read (a file that fails prints its one error line alone), at most one line per kind
/// per file: a file with 500 lines of one fault gets one warning, with the count.

#include <map>
#include <string>
#include <vector>

namespace pathlab {

class InputNotes {
public:
    /// "warning: FILE:LINE: MESSAGE", for what PathLab reads differently from what the file
    /// says; later ones of the same `kind` in `file` only count.
    void warning(const std::string& file, int line, const std::string& kind,
                 const std::string& message);

    /// "note: FILE:LINE: MESSAGE", for what PathLab reads as the file means but some readers
    /// would not; later ones of the same `kind` in `file` only count.
    void note(const std::string& file, int line, const std::string& kind,
              const std::string& message);

    /// A keyword of `file` PathLab reads past, listed in one note per file:
    /// "note: FILE: INTRO word1, word2" (the first few, sorted, then how many more).
    void ignored(const std::string& file, const std::string& intro, const std::string& word);

    /// Prints them to stderr, in the order they were first met.
    void print() const;

private:
    struct Entry {
        const char* severity;
        std::string file;
        int line = 0;
        std::string kind;
        std::string message;
        int count = 1;
        std::vector<std::string> words; ///< for ignored(): sorted, distinct
    };
    void add(const char* severity, const std::string& file, int line, const std::string& kind,
             const std::string& message);
    Entry* find(const std::string& file, const std::string& kind);

    std::vector<Entry> entries_;
};

} // namespace pathlab
