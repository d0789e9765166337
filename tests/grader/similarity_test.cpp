// The class's similarity report: what survives renaming and reformatting, the stub left out of
// every comparison, and the pairs it lists. The hand-written sources below are a made-up
// exercise, not a lab: this file ships in the student release, and must not hold a lab's
// answer. The labs themselves are measured from solutions/ and tests/grader/mutants/, tagged
// [solutions], which only the instructor's kit has.
#include "catch.h"

#include "similarity/similarity.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

using namespace pathlab::grader;

namespace {

const std::string Stub = R"(// Exercise 0: a histogram. Fill in TODO(ex0.1) and TODO(ex0.2).
#include <vector>

namespace exercise {

std::vector<int> histogram(const std::vector<double>& samples, double lo, double hi, int bins) {
    std::vector<int> counts(bins, 0);
    // TODO(ex0.1): the bin of each sample in [lo, hi); skip the others.
    TODO("ex0.1");
    // TODO(ex0.2): a sample that rounds to bin `bins` belongs to the last one.
    TODO("ex0.2");
    return counts;
}

} // namespace exercise
)";

const std::string Original = R"(// Exercise 0: a histogram.
#include <vector>

namespace exercise {

std::vector<int> histogram(const std::vector<double>& samples, double lo, double hi, int bins) {
    std::vector<int> counts(bins, 0);
    const double width = (hi - lo) / bins;
    for (const double x : samples) {
        if (x < lo || x >= hi) continue; // outside the range
        int bin = static_cast<int>((x - lo) / width);
        if (bin >= bins) bin = bins - 1; // rounding at the top
        ++counts[bin];
    }
    return counts;
}

} // namespace exercise
)";

/// The original with every name changed, its layout redone, its comments replaced.
const std::string RenamedAndReformatted = R"(#include <vector>
/* My own histogram, written from scratch. */
namespace exercise
{
std::vector<int> histogram(const std::vector<double> &data, double from, double to, int n)
{
  std::vector<int> result(n, 0);
  const double step = (to - from)
                      / n;
  for (const double value : data)
  {
    if (value < from || value >= to)
      continue;
    int slot = static_cast<int>((value - from) / step);
    if (slot >= n)
      slot = n - 1;
    ++result[slot];
  }
  return result;
}
}
)";

/// The same exercise written without the original: an index loop, the fraction of the range
/// first, one condition for both ends, std::min for the top.
const std::string Independent = R"(// Exercise 0: a histogram.
#include <algorithm>
#include <vector>

namespace exercise {

std::vector<int> histogram(const std::vector<double>& samples, double lo, double hi, int bins) {
    std::vector<int> counts(bins, 0);
    for (size_t i = 0; i < samples.size(); i++) {
        const double t = (samples[i] - lo) / (hi - lo); // 0..1 inside the range
        if (t >= 0.0 && t < 1.0) counts[std::min(bins - 1, int(t * bins))] += 1;
    }
    return counts;
}

} // namespace exercise
)";

/// A stub of many steps, as the labs' are (five TODO markers each, between given lines): each
/// given line followed by a step to write.
const std::string ManyStepStub = R"(double estimate(const Scene& scene, Context& ctx) {
    double total = 0;
    const double light = ctx.light(scene);
    TODO("ex1.1");
    if (light <= 0) return total;
    TODO("ex1.2");
    total += light * scene.area;
    TODO("ex1.3");
    for (int i = 0; i < ctx.count; ++i) total -= ctx.loss[i];
    TODO("ex1.4");
    const bool inside = scene.contains(ctx.point);
    TODO("ex1.5");
    if (!inside) total *= 0.5;
    TODO("ex1.6");
    total = std::max(total, ctx.floor);
    TODO("ex1.7");
    ctx.log("estimate", total);
    return total;
}
)";

/// `text` with every line holding `marker` left out.
std::string withoutLines(const std::string& text, const std::string& marker) {
    std::istringstream lines(text);
    std::string line, kept;
    while (std::getline(lines, line))
        if (line.find(marker) == std::string::npos) kept += line + "\n";
    return kept;
}

/// `text` with its first `from` replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
    return text.replace(text.find(from), from.size(), to);
}

double alike(const std::string& a, const std::string& b, const std::string& stub = Stub) {
    return similarity(normalisedTokens(a), normalisedTokens(b), normalisedTokens(stub));
}

std::string contents(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

const std::filesystem::path KitRoot = std::filesystem::path(PATHLAB_GRADER_DIR) / "..";
const char* const Labs[] = {"branching", "uniform", "importance", "roulette"};

/// `source` disguised by a program, for the lab files: comments dropped, every name other than
/// the keywords the labs use renamed, numbers changed, one statement per line and other
/// spacing. A keyword missing here is renamed too, and shows as a copy scoring below 1.
std::string disguised(const std::string& source) {
    static const std::set<std::string> keywords = {
        "auto",        "bool",         "const", "constexpr", "else",     "false",  "float",
        "for",         "if",           "int",   "namespace", "nullptr",  "return", "static",
        "static_cast", "thread_local", "true",  "void",      "volatile", "while"};
    std::istringstream lines(source);
    std::string line, code, out = "/* all my own work */\n";
    while (std::getline(lines, line)) {
        line = line.substr(0, line.find("//")); // the labs have no "//" inside a string
        const size_t start = line.find_first_not_of(" \t");
        if (start == std::string::npos) continue;
        if (line[start] == '#')
            out += line + "\n";
        else
            code += line.substr(start) + " ";
    }
    const auto isWordChar = [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
    };
    for (size_t i = 0; i < code.size();) {
        size_t end = i + 1;
        if (std::isdigit(static_cast<unsigned char>(code[i]))) { // 1.0f, 0.01f
            while (end < code.size() && (isWordChar(code[end]) || code[end] == '.')) ++end;
            out += "42";
        } else if (isWordChar(code[i])) {
            while (end < code.size() && isWordChar(code[end])) ++end;
            const std::string word = code.substr(i, end - i);
            out += keywords.count(word) ? word : "renamed_" + word + "_2";
        } else if (code[i] == ';') {
            out += " ;\n      ";
        } else if (code[i] == '{' || code[i] == '}') {
            out += std::string("\n") + code[i] + "\n  ";
        } else {
            out += code[i] == '(' ? "( " : code[i] == ')' ? " )" : std::string(1, code[i]);
        }
        i = end;
    }
    return out;
}

} // namespace

TEST_CASE("normalised tokens keep keywords and operators, and nothing a copier can rename",
          "[grader]") {
    using Tokens = std::vector<std::string>;
    CHECK(normalisedTokens("#include <vector>\nint total = a->b + 0x1F; // the sum\n") ==
          Tokens{"int", "id", "=", "id", "->", "id", "+", "0", ";"});
    // Every number is "0", every string and character literal "\"\"", raw and prefixed alike.
    CHECK(normalisedTokens("f(1.5e-3f, 1'000, .5, \"a \\\" b\", 'x', u8\"s\", R\"d(\")d\")") ==
          Tokens{"id", "(", "0", ",", "0", ",", "0", ",", "\"\"", ",", "\"\"", ",", "\"\"", ",",
                 "\"\"", ")"});
    // Operators whole, as the compiler reads them; `and` is `&&`; `>>` two `>`, so that
    // `vector<vector<int>>` and `vector<vector<int> >` read the same.
    CHECK(normalisedTokens("a::b += i++ <= j && k and not m;") ==
          Tokens{"id", "::", "id", "+=", "id", "++", "<=", "id", "&&", "id", "&&", "!", "id", ";"});
    CHECK(normalisedTokens("v<v<int>> x;") == normalisedTokens("v<v<int> > x;"));
    // A directive ends at its line's end, after a continuation and a comment across lines.
    CHECK(normalisedTokens("  #define TWICE(x) \\\n  ((x) + (x)) /* a\nb */ + 1\nreturn 0;") ==
          Tokens{"return", "0", ";"});
    CHECK(normalisedTokens("/* all */ // of it\n  \t").empty());
}

TEST_CASE("a renamed and reformatted copy scores at least 0.95", "[grader]") {
    CHECK(normalisedTokens(RenamedAndReformatted) == normalisedTokens(Original));
    CHECK(alike(Original, RenamedAndReformatted) >= 0.95);
    CHECK(alike(RenamedAndReformatted, Original) == alike(Original, RenamedAndReformatted));
}

TEST_CASE("a copy that changed only comments scores 1", "[grader]") {
    std::string recommented = replaced(Original, " // outside the range", "/* a skip */");
    recommented = replaced(recommented, "// rounding at the top", "// clamped, or it overflows\n");
    recommented = replaced(recommented, "// Exercise 0: a histogram.", "/* Written alone.\n */");
    CHECK(alike(Original, recommented) == 1.0);
    CHECK(alike(Original, withoutLines(Original, "// Exercise 0")) == 1.0);
}

TEST_CASE("a file left as the stub is alike to nothing", "[grader]") {
    CHECK(alike(Stub, Stub) == 0.0);
    CHECK(alike(Stub, Original) == 0.0);
    CHECK(alike(Original, Stub) == 0.0);
    CHECK(alike(withoutLines(Stub, "TODO"), Original) == 0.0);
    // With only its TODO lines deleted a stub has k-grams that are not the stub's, across each
    // deletion (seven here, more than enough to be compared), and not one token of its own: two
    // such files are not a copy of each other.
    const std::string todosDeleted = withoutLines(ManyStepStub, "TODO");
    CHECK(alike(todosDeleted, todosDeleted, ManyStepStub) == 0.0);
    // Nor is the stub's code written out again (which a diff shows as added) a student's own.
    const std::string givenTwice = ManyStepStub + ManyStepStub;
    CHECK(alike(givenTwice, givenTwice, ManyStepStub) == 0.0);
}

TEST_CASE("a file sharing only the stub with another scores below the threshold", "[grader]") {
    // Enough code of its own to be compared (alike to itself), and little of it the original's.
    REQUIRE(alike(Independent, Independent) == 1.0);
    const double independent = alike(Independent, Original);
    CHECK(independent < DefaultSimilarityThreshold);
    CHECK(independent < 0.5);
    // Too little of its own (one line) to be alike to anything, even to a copy of itself.
    const std::string oneLine = replaced(
        Stub, "TODO(\"ex0.1\");",
        "for (const double x : samples) ++counts[static_cast<int>((x - lo) / (hi - lo) * bins)];");
    CHECK(alike(oneLine, oneLine) == 0.0);
    // Without the stub taken out, the shared signature and return alone would make these alike.
    CHECK(alike(Independent, Original, "") > independent);
}

TEST_CASE("the class's pairs: most alike first, no submission with itself, each lab apart",
          "[grader]") {
    const std::string oneBug = withoutLines(Original, "rounding at the top");
    const std::vector<SubmittedFile> files = {
        {"alice", "histogram", Original},
        {"bob", "histogram", RenamedAndReformatted},
        {"carol", "histogram", oneBug},
        {"dave", "histogram", Independent},
        {"erin", "histogram", Stub},
        {"frank", "histogram", Stub},
        // alice's file twice (a resubmission merged in): never alike to herself, and each of
        // her pairs listed once.
        {"alice", "histogram", Original},
        // Another lab, with alice's histogram as its file: not compared with the histograms.
        {"grace", "mean", Original},
        {"heidi", "mean", Independent},
    };
    const std::vector<SimilarPair> pairs = similarPairs(files, {{"histogram", Stub}}, 0.5);

    // alice-bob (1.0) first; then carol with each of them, equally alike, in the order of names.
    REQUIRE(pairs.size() == 3);
    CHECK(pairs[0].first == "alice");
    CHECK(pairs[0].second == "bob");
    CHECK(pairs[0].similarity == Approx(1.0));
    CHECK(pairs[1].first == "alice");
    CHECK(pairs[1].second == "carol");
    CHECK(pairs[2].first == "bob");
    CHECK(pairs[2].second == "carol");
    CHECK(pairs[1].similarity == pairs[2].similarity);
    CHECK(pairs[1].similarity >= DefaultSimilarityThreshold);
    CHECK(pairs[1].similarity < 1.0);
    for (const SimilarPair& pair : pairs) {
        CHECK(pair.lab == "histogram");
        CHECK(pair.first < pair.second);
    }
    CHECK(similarPairs(files, {{"histogram", Stub}}).size() == 3); // DefaultSimilarityThreshold
    // grace and heidi's lab has no stub given: compared whole, and still with each other only.
    const std::vector<SimilarPair> everything = similarPairs(files, {{"histogram", Stub}}, 0.0);
    for (const SimilarPair& pair : everything) {
        CHECK(pair.first != pair.second);
        CHECK((pair.lab == "mean") == (pair.first == "grace" && pair.second == "heidi"));
        if (pair.lab == "mean") CHECK(pair.similarity == Approx(alike(Original, Independent, "")));
    }
    CHECK(std::is_sorted(
        everything.begin(), everything.end(),
        [](const SimilarPair& a, const SimilarPair& b) { return a.similarity > b.similarity; }));
}

TEST_CASE("the reference solutions: disguised 1, stub 0, mutants near copies",
          "[grader][solutions]") {
    const std::filesystem::path mutantsFolder = KitRoot / "tests" / "grader" / "mutants";
    std::vector<double> mutants;
    for (const char* lab : Labs) {
        const std::string file = std::string(lab) + ".cpp";
        const std::string stub = contents(KitRoot / "labs" / file);
        const std::string solution = contents(KitRoot / "solutions" / file);
        REQUIRE_FALSE(solution.empty());
        INFO(lab);
        CHECK(alike(solution, disguised(solution), stub) >= 0.95);
        CHECK(alike(stub, solution, stub) == 0.0);
        for (const auto& mutant : std::filesystem::directory_iterator(mutantsFolder)) {
            if (!std::filesystem::exists(mutant.path() / file)) continue;
            INFO(mutant.path().filename().string());
            const double score = alike(solution, contents(mutant.path() / file), stub);
            // Copies of the solution with one bug, which at most rewrites a third of the lab
            // (0.515 at the least): above independent labs (0.26 at most, similarity.h).
            CHECK(score >= 0.4);
            mutants.push_back(score);
        }
    }
    REQUIRE(mutants.size() >= 10);
    std::sort(mutants.begin(), mutants.end());
    CHECK(mutants[mutants.size() / 2] >= DefaultSimilarityThreshold);
}
