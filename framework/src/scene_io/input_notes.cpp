#include "pathlab/scene_io/input_notes.h"

#include "pathlab/support/printable_text.h"

#include <algorithm>
#include <cstdio>

namespace pathlab {

namespace {

// A file of garbage has as many "keywords" as lines; the first few say enough.
constexpr size_t listedWords = 12;

} // namespace

InputNotes::Entry* InputNotes::find(const std::string& file, const std::string& kind) {
    for (Entry& entry : entries_)
        if (entry.file == file && entry.kind == kind) return &entry;
    return nullptr;
}

void InputNotes::add(const char* severity, const std::string& file, int line,
                     const std::string& kind, const std::string& message) {
    if (Entry* entry = find(file, kind)) {
        ++entry->count;
        return;
    }
    entries_.push_back({severity, file, line, kind, message, 1, {}});
}

void InputNotes::warning(const std::string& file, int line, const std::string& kind,
                         const std::string& message) {
    add("warning", file, line, kind, message);
}

void InputNotes::note(const std::string& file, int line, const std::string& kind,
                      const std::string& message) {
    add("note", file, line, kind, message);
}

void InputNotes::ignored(const std::string& file, const std::string& intro,
                         const std::string& word) {
    Entry* entry = find(file, intro);
    if (!entry) {
        entries_.push_back({"note", file, 0, intro, intro, 0, {}});
        entry = &entries_.back();
    }
    const auto at = std::lower_bound(entry->words.begin(), entry->words.end(), word);
    if (at == entry->words.end() || *at != word) entry->words.insert(at, word);
}

void InputNotes::print() const {
    for (const Entry& entry : entries_) {
        std::string where = printableText(entry.file);
        if (entry.line > 0) where += ":" + std::to_string(entry.line);
        std::string text = entry.message;
        if (!entry.words.empty()) {
            for (size_t i = 0; i < std::min(entry.words.size(), listedWords); ++i)
                text += (i == 0 ? "" : ", ") + printableText(entry.words[i]);
            if (entry.words.size() > listedWords)
                text += " and " + std::to_string(entry.words.size() - listedWords) + " more";
        } else if (entry.count > 1) {
            text += " (and " + std::to_string(entry.count - 1) + " more like it)";
        }
        std::fprintf(stderr, "%s: %s: %s\n", entry.severity, where.c_str(), text.c_str());
    }
}

} // namespace pathlab
