// A class's similar pairs as clusters (reports/similarity_clusters.h) and their side-by-side pages
// (similarity/side_by_side.h).
#include "catch.h"

#include "reports/similarity_clusters.h"
#include "similarity/side_by_side.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

using namespace pathlab::grader;
namespace fs = std::filesystem;

TEST_CASE("similar pairs grouped per lab into the submissions a chain of alike files joins",
          "[grader]") {
    // Lab 1: a, b, c chained (a-b, b-c) and d-e apart; lab 2: a-b again.
    const std::vector<SimilarLabs> pairs = {{"a", "b", "branching", 0.95},
                                            {"b", "c", "branching", 0.80},
                                            {"d", "e", "branching", 0.99},
                                            {"a", "b", "uniform", 0.90}};
    const std::vector<SimilarCluster> clusters = similarClusters(pairs);
    REQUIRE(clusters.size() == 3);
    CHECK(clusters[0].lab == "branching"); // the most alike first: d-e at 0.99
    REQUIRE(clusters[0].members.size() == 2);
    CHECK(clusters[0].members[0].id == "d");
    CHECK(clusters[1].lab == "branching");
    REQUIRE(clusters[1].members.size() == 3);
    CHECK(clusters[1].pairs == 2);
    CHECK(clusters[1].mostAlike == 0.95);
    // Each member with the one it is most like: c's only pair is with b; b is more like a.
    CHECK(clusters[1].members[1].id == "b");
    CHECK(clusters[1].members[1].nearest.first == "a");
    CHECK(clusters[1].members[2].id == "c");
    CHECK(clusters[1].members[2].nearest.second == "c");
    CHECK(clusters[2].lab == "uniform");
    CHECK(clusters[2].members.size() == 2);
    // One row per cluster, each member linked to its pair's page.
    const std::string html = clustersHtml(clusters);
    CHECK(html.find("<tr><td>branching</td><td>3</td><td>2</td><td>95%</td>") != std::string::npos);
    CHECK(html.find("c &harr; <a href=\"" + sideBySidePage(pairs[1]) + "\">b (80%)</a>") !=
          std::string::npos);
    CHECK(sideBySidePage(pairs[0]) != sideBySidePage(pairs[3])); // same ids, another lab
}

TEST_CASE("a side-by-side page shows both files, marks their shared lines, escapes the text",
          "[grader]") {
    const fs::path out = fs::temp_directory_path() / ("pathlab-side-" + std::to_string(::getpid()));
    for (const char* id : {"amy", "ben"})
        fs::create_directories(out / "submissions" / id / "submitted");
    std::ofstream(out / "submissions" / "amy" / "submitted" / "uniform.cpp")
        << "int shared = 1;\nif (a < b) return;\n";
    std::ofstream(out / "submissions" / "ben" / "submitted" / "uniform.cpp")
        << "int   shared = 1;\nint only_ben;\n";
    const SimilarLabs pair{"amy", "ben", "uniform", 0.9};
    writeSideBySidePages(out.string(), similarClusters({pair}));
    std::ifstream in(out / sideBySidePage(pair));
    std::ostringstream page;
    page << in.rdbuf();
    const std::string html = page.str();
    CHECK(html.find("<span class=\"same\">int shared = 1;</span>") != std::string::npos);
    CHECK(html.find("<span class=\"same\">int   shared = 1;</span>") != std::string::npos);
    CHECK(html.find("<span>if (a &lt; b) return;</span>") != std::string::npos);
    CHECK(html.find("<span>int only_ben;</span>") != std::string::npos);
    fs::remove_all(out);
}
