#pragma once
/// Which submissions of a class have suspiciously alike lab files: a copy of another student's
/// labs, or of the reference solutions, with its names changed and its layout redone. A hint for
/// the instructor, who reads the two files side by side; never a grade, and never proof: a lab
/// whose handout dictates most lines leaves independent work little room to differ.

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace pathlab::grader {

/// Where a pair is listed. Measured on the kit's labs (k = 12, 48 k-grams of one's own):
///  - solutions/ renamed, laid out anew and recommented, against themselves: 1.0;
///  - the 24 mutants (tests/grader/mutants/: a solution with one bug) against their solution:
///    median 0.91, and 0.772 or more for the 21 whose bug takes a few lines (lowest:
///    uniform_no_divide); the 3 that rewrote a third of the lab 0.52-0.61, as alike as honest work;
///  - labs 2-4 written independently for the measurement (7 of them, not kept): 0.10-0.26
///    against the solution, 0.04-0.32 against each other, but 0.705 for a lab 3 that follows the
///    handout's words (the strengths, their sum, the cutoff) as the solution does;
///  - lab 1 dictates nearly every statement: two independent labs 1 written by the handout scored
///    0.70 and 0.875 against the solution (0.19 for one in a style of its own). A pair alike in
///    lab 1 alone is weak evidence.
/// 0.75 lies between honest work (0.705 at most, lab 1 aside) and copies with a few lines changed
/// (0.772 at least). It finds lazy copies only: a copy with every statement edited a little
/// (operands swapped, += spelled out) scored 0.195.
constexpr double DefaultSimilarityThreshold = 0.75;

/// A C++ source reduced to what survives renaming and reformatting: comments and whitespace
/// dropped, every identifier that is not a C++ keyword -> "id", number literals -> "0",
/// string/char literals -> "\"\"". Keeps keywords, operators and punctuation (multi-char
/// operators as one token: ->, ::, ++, +=, <=, &&, ...; `>>` as two `>`, as template brackets
/// may be written either way; `and`, `not`... as the operators they spell). Preprocessor lines
/// (#include ...) are dropped.
std::vector<std::string> normalisedTokens(const std::string& source);

/// How alike two token streams are, 0..1, ignoring what both share with `base` (the stub file
/// every student starts from): the k-grams of 12 tokens of each that are its own (not the
/// stub's, and holding a token that a diff against the stub shows as added), then
/// |A ∩ B| / min(|A|, |B|) (containment: a copy scores 1 however much was added to it). 0 when
/// either has fewer than 48 k-grams of its own (half a lab): a file left as the stub, or with
/// only its TODO lines deleted, is alike to nothing.
double similarity(const std::vector<std::string>& a, const std::vector<std::string>& b,
                  const std::vector<std::string>& base);

/// The kit's reference solutions' name among a class's submissions.
inline constexpr const char* KitSolutions = "reference solutions";

struct SubmittedFile {
    /// This term's file.
    SubmittedFile(std::string submission, std::string lab, std::string source)
        : submission(std::move(submission)), lab(std::move(lab)), source(std::move(source)) {}
    /// An earlier term's file, its tokens only.
    SubmittedFile(std::string submission, std::string lab, std::vector<std::string> tokens)
        : submission(std::move(submission)), lab(std::move(lab)), prior(true),
          tokens(std::move(tokens)) {}

    std::string submission; ///< the submission's id in the gradebook
    std::string lab;        ///< "branching", "uniform", ...
    std::string source;     ///< the lab file's text
    /// An earlier term's file (prior_terms.h): its normalised tokens only, no source. Compared
    /// with this term's files, never with another earlier term's.
    bool prior = false;
    std::vector<std::string> tokens;
};

struct SimilarPair {
    std::string first, second; ///< the two submissions, in alphabetical order
    std::string lab;
    double similarity = 0;
};

/// Every pair of submissions whose file of the same lab is at least `threshold` alike (each lab
/// compared with the same lab's files only, `bases` maps lab name -> stub source; a lab without
/// a stub there is compared whole), most alike first. A submission is never paired with itself,
/// nor an earlier term's file with another's.
std::vector<SimilarPair> similarPairs(const std::vector<SubmittedFile>& files,
                                      const std::map<std::string, std::string>& bases,
                                      double threshold = DefaultSimilarityThreshold);

} // namespace pathlab::grader
