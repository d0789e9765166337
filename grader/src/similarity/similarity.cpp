#include "similarity/similarity.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <iterator>
#include <sstream>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

namespace pathlab::grader {

namespace {

// ---- Tokens ----------------------------------------------------------------------------------

std::unordered_set<std::string> wordsOf(const char* list) {
    std::istringstream words(list);
    return {std::istream_iterator<std::string>(words), std::istream_iterator<std::string>()};
}

/// C++17's keywords, and C++20's, which no C++17 lab uses as a name. Kept as they are: `if`,
/// `for` and `return` are the structure that renaming leaves.
const std::unordered_set<std::string>& keywords() {
    static const std::unordered_set<std::string> words = wordsOf(
        "alignas alignof asm auto bool break case catch char char8_t char16_t char32_t class "
        "co_await co_return co_yield concept const consteval constexpr constinit const_cast "
        "continue decltype default delete do double dynamic_cast else enum explicit export "
        "extern false float for friend goto if inline int long mutable namespace new noexcept "
        "nullptr operator private protected public register reinterpret_cast requires return "
        "short signed sizeof static static_assert static_cast struct switch template this "
        "thread_local throw true try typedef typeid typename union unsigned using virtual void "
        "volatile wchar_t while");
    return words;
}

/// The alternative tokens are the operators they spell: `and` for `&&` is a rewording, not a
/// different program.
const std::unordered_map<std::string, std::string>& alternativeTokens() {
    static const std::unordered_map<std::string, std::string> spelled = {
        {"and", "&&"},   {"and_eq", "&="}, {"bitand", "&"},  {"bitor", "|"},
        {"compl", "~"},  {"not", "!"},     {"not_eq", "!="}, {"or", "||"},
        {"or_eq", "|="}, {"xor", "^"},     {"xor_eq", "^="}};
    return spelled;
}

/// Longest first, so that each operator is taken whole (maximal munch). `>>` is not among them:
/// as two `>` it reads the same whether a template's brackets were closed as `>>` or `> >`.
constexpr const char* MultiCharOperators[] = {
    "<=>", "<<=", ">>=", "->*", "...", "::", "->", ".*", "++", "--", "+=", "-=", "*=",
    "/=",  "%=",  "&=",  "|=",  "^=",  "<<", "<=", ">=", "==", "!=", "&&", "||", "##"};

bool isIdentifierStart(char c) {
    // Bytes above 127 are UTF-8 letters, which C++ allows in names; GCC allows '$' too.
    return std::isalpha(static_cast<unsigned char>(c)) || c == '_' || c == '$' ||
           static_cast<unsigned char>(c) >= 0x80;
}

bool isIdentifierChar(char c) {
    return isIdentifierStart(c) || std::isdigit(static_cast<unsigned char>(c));
}

bool isDigit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

bool isExponentMark(char c) { return c == 'e' || c == 'E' || c == 'p' || c == 'P'; }

bool startsWith(const std::string& text, size_t at, const char* prefix) {
    return text.compare(at, std::char_traits<char>::length(prefix), prefix) == 0;
}

/// The source with its line splices (backslash-newline) removed, as the compiler's second phase
/// removes them: a directive continued on the next line is still one line.
std::string splicedLines(const std::string& source) {
    std::string spliced;
    spliced.reserve(source.size());
    for (size_t i = 0; i < source.size(); ++i) {
        if (source[i] == '\\' && i + 1 < source.size() && source[i + 1] == '\n') {
            ++i;
        } else if (source[i] == '\\' && startsWith(source, i + 1, "\r\n")) {
            i += 2;
        } else {
            spliced += source[i];
        }
    }
    return spliced;
}

size_t endOfLine(const std::string& text, size_t from) {
    const size_t newline = text.find('\n', from);
    return newline == std::string::npos ? text.size() : newline;
}

size_t endOfBlockComment(const std::string& text, size_t from) {
    const size_t close = text.find("*/", from + 2);
    return close == std::string::npos ? text.size() : close + 2;
}

/// After the opening quote at `from`: past the closing one, or at the end of the line for an
/// unterminated literal (which the compiler rejects; it should not swallow the file here).
size_t endOfQuoted(const std::string& text, size_t from) {
    const char quote = text[from];
    size_t i = from + 1;
    while (i < text.size() && text[i] != quote && text[i] != '\n') i += text[i] == '\\' ? 2 : 1;
    return std::min(text.size(), i < text.size() && text[i] == quote ? i + 1 : i);
}

/// R"delimiter( ... )delimiter", from its opening quote at `from`.
size_t endOfRawString(const std::string& text, size_t from) {
    const size_t open = text.find('(', from);
    if (open == std::string::npos || open - from > 17) return endOfQuoted(text, from);
    const std::string close = ")" + text.substr(from + 1, open - from - 1) + "\"";
    const size_t end = text.find(close, open);
    return end == std::string::npos ? text.size() : end + close.size();
}

/// A preprocessing number (digits, '.', letters, exponent signs, digit separators), which
/// covers 1.0f, 0x1p-3, 1e+9, 1'000 and 42ull alike.
size_t endOfNumber(const std::string& text, size_t from) {
    size_t i = from + 1;
    while (i < text.size()) {
        const char c = text[i];
        const bool exponentSign = (c == '+' || c == '-') && isExponentMark(text[i - 1]);
        const bool separator = c == '\'' && i + 1 < text.size() && isIdentifierChar(text[i + 1]);
        if (!(isIdentifierChar(c) || c == '.' || exponentSign || separator)) break;
        ++i;
    }
    return i;
}

size_t endOfIdentifier(const std::string& text, size_t from) {
    size_t i = from;
    while (i < text.size() && isIdentifierChar(text[i])) ++i;
    return i;
}

/// An identifier directly before a quote that makes it a literal's prefix: u8"..", L'x', R"(..)".
bool isLiteralPrefix(const std::string& word) {
    static const std::unordered_set<std::string> prefixes = {"L",  "u",  "U",  "u8", "R",
                                                             "LR", "uR", "UR", "u8R"};
    return prefixes.count(word) > 0;
}

size_t operatorLength(const std::string& text, size_t at) {
    for (const char* op : MultiCharOperators)
        if (startsWith(text, at, op)) return std::char_traits<char>::length(op);
    return 1;
}

/// A string or character literal starting at `from` (its prefix included), with any
/// user-defined suffix ("text"s): its end.
size_t endOfLiteral(const std::string& text, size_t from, size_t quote) {
    const bool raw = quote > from && text[quote - 1] == 'R';
    const size_t end = raw ? endOfRawString(text, quote) : endOfQuoted(text, quote);
    return endOfIdentifier(text, end);
}

/// One token of code starting at `at` (no whitespace, comment or line start there): its end and
/// what it normalises to.
std::pair<size_t, std::string> tokenAt(const std::string& text, size_t at) {
    const char c = text[at];
    if (c == '"' || c == '\'') return {endOfLiteral(text, at, at), "\"\""};
    if (isDigit(c) || (c == '.' && at + 1 < text.size() && isDigit(text[at + 1])))
        return {endOfNumber(text, at), "0"};
    if (isIdentifierStart(c)) {
        const size_t end = endOfIdentifier(text, at);
        const std::string word = text.substr(at, end - at);
        if (end < text.size() && (text[end] == '"' || text[end] == '\'') && isLiteralPrefix(word))
            return {endOfLiteral(text, at, end), "\"\""};
        if (keywords().count(word)) return {end, word};
        const auto alternative = alternativeTokens().find(word);
        if (alternative != alternativeTokens().end()) return {end, alternative->second};
        return {end, "id"};
    }
    const size_t length = operatorLength(text, at);
    return {at + length, text.substr(at, length)};
}

// ---- Fingerprints ----------------------------------------------------------------------------

/// k: a k-gram of 12 tokens is about one line of code. Shorter ones match between any two
/// programs that call the same API (`id . id ( id , id . id . id ( ) )`); longer ones miss a
/// copy whose every other line was touched.
constexpr size_t GramTokens = 12;

/// A file with fewer k-grams of its own than this is alike to nothing. One added token makes up
/// to 12 of them: the depth limit's one line, which every student writes alike, makes 21, and
/// scored 0.95 against the whole of solutions/branching.cpp. 48 is half of what the shortest
/// reference solution has of its own (lab 1, 96): less than half a lab is too little for a
/// match to tell copying from the lines the handout dictates.
constexpr size_t MinimumOwnGrams = 48;

/// The alignment of a file with its stub is skipped past this many cells (tokens x stub tokens,
/// 2 bytes each: 8 MiB, and no common subsequence longer than 2048 to overflow one): a file that
/// large is no stub with lines deleted, and its few k-grams across deletions weigh nothing
/// beside its own code. A lab against its stub is some 300 x 120.
constexpr size_t MaxAlignmentCells = size_t(1) << 22;

using Hash = std::uint64_t;

/// FNV-1a: the same 64 bits for the same bytes on every platform and in every run.
Hash fnv1a(const std::string& bytes, Hash hash = 14695981039346656037ull) {
    for (const unsigned char byte : bytes) hash = (hash ^ byte) * 1099511628211ull;
    return hash;
}

std::vector<Hash> tokenHashes(const std::vector<std::string>& tokens) {
    std::vector<Hash> hashes;
    hashes.reserve(tokens.size());
    for (const std::string& token : tokens) hashes.push_back(fnv1a(token));
    return hashes;
}

Hash gramHash(const std::vector<Hash>& tokens, size_t first) {
    Hash hash = 14695981039346656037ull;
    for (size_t i = first; i < first + GramTokens; ++i)
        for (int byte = 0; byte < 8; ++byte)
            hash = (hash ^ ((tokens[i] >> (8 * byte)) & 0xff)) * 1099511628211ull;
    return hash;
}

/// Sorted and unique, for containment()'s merge and binary_search.
std::vector<Hash> sortedUnique(std::vector<Hash> hashes) {
    std::sort(hashes.begin(), hashes.end());
    hashes.erase(std::unique(hashes.begin(), hashes.end()), hashes.end());
    return hashes;
}

std::vector<Hash> allGrams(const std::vector<Hash>& tokens) {
    std::vector<Hash> grams;
    for (size_t first = 0; first + GramTokens <= tokens.size(); ++first)
        grams.push_back(gramHash(tokens, first));
    return sortedUnique(std::move(grams));
}

/// Which of `tokens` a diff against `base` shows as added: those outside one longest common
/// subsequence of the two. Not the base's k-grams alone: a stub with its TODO lines deleted has
/// k-grams that are not the stub's (across each deletion) and no token of its own.
std::vector<bool> addedTokens(const std::vector<Hash>& tokens, const std::vector<Hash>& base) {
    std::vector<bool> added(tokens.size(), true);
    // The common start and end, as diff takes them, keep the table to the part that changed.
    size_t head = 0;
    while (head < tokens.size() && head < base.size() && tokens[head] == base[head])
        added[head++] = false;
    size_t tail = 0;
    while (tail < tokens.size() - head && tail < base.size() - head &&
           tokens[tokens.size() - 1 - tail] == base[base.size() - 1 - tail]) {
        added[tokens.size() - 1 - tail] = false;
        ++tail;
    }
    const size_t n = tokens.size() - head - tail, m = base.size() - head - tail;
    if (n == 0 || m == 0 || n * m > MaxAlignmentCells) return added;

    // lengths[i][j]: the longest common subsequence of the changed parts' last n-i and m-j
    // tokens; then walk it from the start, marking the tokens it keeps.
    std::vector<std::uint16_t> lengths((n + 1) * (m + 1), 0);
    const auto at = [m](size_t i, size_t j) { return i * (m + 1) + j; };
    for (size_t i = n; i-- > 0;)
        for (size_t j = m; j-- > 0;)
            lengths[at(i, j)] = tokens[head + i] == base[head + j]
                                    ? lengths[at(i + 1, j + 1)] + 1
                                    : std::max(lengths[at(i + 1, j)], lengths[at(i, j + 1)]);
    for (size_t i = 0, j = 0; i < n && j < m;) {
        if (tokens[head + i] == base[head + j]) {
            added[head + i] = false;
            ++i, ++j;
        } else if (lengths[at(i + 1, j)] >= lengths[at(i, j + 1)]) {
            ++i;
        } else {
            ++j;
        }
    }
    return added;
}

/// The k-grams a file has of its own: not the stub's, and holding a token the student added.
std::vector<Hash> ownGrams(const std::vector<std::string>& source, const std::vector<Hash>& base,
                           const std::vector<Hash>& baseGrams) {
    const std::vector<Hash> tokens = tokenHashes(source);
    const std::vector<bool> added = addedTokens(tokens, base);
    std::vector<Hash> own;
    size_t lastAdded = SIZE_MAX; // the latest added token at or before a k-gram's end
    for (size_t end = 0; end < tokens.size(); ++end) {
        if (added[end]) lastAdded = end;
        if (end + 1 < GramTokens) continue;
        const size_t first = end + 1 - GramTokens;
        if (lastAdded == SIZE_MAX || lastAdded < first) continue;
        const Hash gram = gramHash(tokens, first);
        if (!std::binary_search(baseGrams.begin(), baseGrams.end(), gram)) own.push_back(gram);
    }
    return sortedUnique(std::move(own));
}

/// |A ∩ B| / min(|A|, |B|): a copy that kept all of one file scores 1 however much it added.
double containment(const std::vector<Hash>& a, const std::vector<Hash>& b) {
    if (a.size() < MinimumOwnGrams || b.size() < MinimumOwnGrams) return 0;
    size_t shared = 0;
    for (size_t i = 0, j = 0; i < a.size() && j < b.size();) {
        if (a[i] < b[j]) {
            ++i;
        } else if (b[j] < a[i]) {
            ++j;
        } else {
            ++shared, ++i, ++j;
        }
    }
    return static_cast<double>(shared) / static_cast<double>(std::min(a.size(), b.size()));
}

/// The stub of a lab, ready to subtract: its tokens (to align with) and its k-grams.
struct Base {
    std::vector<Hash> tokens;
    std::vector<Hash> grams;
};

Base baseOf(const std::vector<std::string>& stub) {
    Base base{tokenHashes(stub), {}};
    base.grams = allGrams(base.tokens);
    return base;
}

/// Most alike first; ties in the order of lab and names, so that a report reads the same twice.
bool listedBefore(const SimilarPair& a, const SimilarPair& b) {
    if (a.similarity != b.similarity) return a.similarity > b.similarity;
    return std::tie(a.lab, a.first, a.second) < std::tie(b.lab, b.first, b.second);
}

/// Whether two files are an earlier term's with another earlier term's or with the kit's
/// solutions: compared in that term, not again.
bool comparedInItsOwnTerm(const SubmittedFile& a, const SubmittedFile& b) {
    const auto earlierOrKit = [](const SubmittedFile& f) {
        return f.prior || f.submission == KitSolutions;
    };
    return (a.prior && earlierOrKit(b)) || (b.prior && earlierOrKit(a));
}

/// The pairs of one lab's files (`own` holds each file's own k-grams) at least `threshold`
/// alike, added to `pairs`. Each pair of submissions once: one that sent a lab's file twice is
/// listed by the more alike of the two.
void addSimilarPairs(const std::string& lab, const std::vector<const SubmittedFile*>& files,
                     const std::vector<std::vector<Hash>>& own, double threshold,
                     std::vector<SimilarPair>& pairs) {
    std::map<std::pair<std::string, std::string>, double> mostAlike;
    for (size_t i = 0; i < files.size(); ++i)
        for (size_t j = i + 1; j < files.size(); ++j) {
            if (files[i]->submission == files[j]->submission) continue;
            if (comparedInItsOwnTerm(*files[i], *files[j])) continue;
            const double alike = containment(own[i], own[j]);
            if (alike < threshold) continue;
            const auto [first, second] = std::minmax(files[i]->submission, files[j]->submission);
            const auto [listed, isNew] = mostAlike.try_emplace({first, second}, alike);
            if (!isNew) listed->second = std::max(listed->second, alike);
        }
    for (const auto& [names, alike] : mostAlike)
        pairs.push_back({names.first, names.second, lab, alike});
}

} // namespace

std::vector<std::string> normalisedTokens(const std::string& source) {
    const std::string text = splicedLines(source);
    std::vector<std::string> tokens;
    bool lineStart = true, inDirective = false;
    for (size_t i = 0; i < text.size();) {
        const char c = text[i];
        if (c == '\n') {
            lineStart = true, inDirective = false;
            ++i;
        } else if (std::isspace(static_cast<unsigned char>(c))) {
            ++i;
        } else if (startsWith(text, i, "//")) {
            i = endOfLine(text, i);
        } else if (startsWith(text, i, "/*")) {
            // A comment is a space: a directive goes on after one that spans lines.
            i = endOfBlockComment(text, i);
        } else {
            if (c == '#' && lineStart) inDirective = true;
            lineStart = false;
            auto [end, token] = tokenAt(text, i);
            if (!inDirective) tokens.push_back(std::move(token));
            i = end;
        }
    }
    return tokens;
}

double similarity(const std::vector<std::string>& a, const std::vector<std::string>& b,
                  const std::vector<std::string>& base) {
    const Base stub = baseOf(base);
    return containment(ownGrams(a, stub.tokens, stub.grams), ownGrams(b, stub.tokens, stub.grams));
}

std::vector<SimilarPair> similarPairs(const std::vector<SubmittedFile>& files,
                                      const std::map<std::string, std::string>& bases,
                                      double threshold) {
    std::map<std::string, std::vector<const SubmittedFile*>> byLab;
    for (const SubmittedFile& file : files) byLab[file.lab].push_back(&file);

    std::vector<SimilarPair> pairs;
    for (const auto& [lab, labFiles] : byLab) {
        const auto stub = bases.find(lab);
        const Base base = baseOf(stub == bases.end() ? std::vector<std::string>{}
                                                     : normalisedTokens(stub->second));
        // Each file's own k-grams once, not once per pair: a class of n has n(n-1)/2 pairs.
        std::vector<std::vector<Hash>> own;
        for (const SubmittedFile* file : labFiles)
            own.push_back(ownGrams(file->prior ? file->tokens : normalisedTokens(file->source),
                                   base.tokens, base.grams));
        addSimilarPairs(lab, labFiles, own, threshold, pairs);
    }
    std::sort(pairs.begin(), pairs.end(), listedBefore);
    return pairs;
}

} // namespace pathlab::grader
