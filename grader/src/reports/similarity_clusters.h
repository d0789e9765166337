#pragma once
/// The similar pairs of a class grouped into clusters: per lab, the submissions joined by a
/// chain of alike files. A handout's dictated lines can make hundreds of students alike, which as
/// pairs is n(n-1)/2 rows; as a cluster it is one row, each member with the one it is most like.

#include "reports/gradebook.h"

#include <string>
#include <vector>

namespace pathlab::grader {

struct SimilarCluster {
    std::string lab;
    /// Each member and the pair with the member it is most like, members in alphabetical order.
    struct Member {
        std::string id;
        SimilarLabs nearest;
    };
    std::vector<Member> members;
    size_t pairs = 0;     ///< the pairs alike beyond the threshold inside the cluster
    double mostAlike = 0; ///< the highest similarity inside
};

/// Connected groups of `pairs` per lab, the most alike first.
std::vector<SimilarCluster> similarClusters(const std::vector<SimilarLabs>& pairs);

/// Where a pair's side-by-side page is, relative to the batch's folder: similarity/LAB-HASH.html,
/// named by a hash of the two ids (ids may hold characters a file name should not).
std::string sideBySidePage(const SimilarLabs& pair);

/// The summary's table of `clusters`, each member linked to its side-by-side page.
std::string clustersHtml(const std::vector<SimilarCluster>& clusters);

} // namespace pathlab::grader
