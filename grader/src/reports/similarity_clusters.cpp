#include "reports/similarity_clusters.h"

#include "common/content_hash.h"
#include "reports/reports.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <utility>

namespace pathlab::grader {

namespace {

/// Union-find over the ids of one lab's pairs.
class Groups {
public:
    size_t of(const std::string& id) {
        const auto [it, added] = index_.emplace(id, parent_.size());
        if (added) parent_.push_back(parent_.size());
        return root(it->second);
    }
    void join(const std::string& a, const std::string& b) { parent_[of(a)] = of(b); }

private:
    size_t root(size_t i) {
        while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
        return i;
    }
    std::map<std::string, size_t> index_;
    std::vector<size_t> parent_;
};

} // namespace

std::vector<SimilarCluster> similarClusters(const std::vector<SimilarLabs>& pairs) {
    std::map<std::string, std::vector<const SimilarLabs*>> byLab;
    for (const SimilarLabs& p : pairs) byLab[p.lab].push_back(&p);
    std::vector<SimilarCluster> clusters;
    for (const auto& [lab, labPairs] : byLab) {
        Groups groups;
        for (const SimilarLabs* p : labPairs) groups.join(p->first, p->second);
        std::map<size_t, SimilarCluster> found;
        std::map<std::string, const SimilarLabs*> nearest;
        for (const SimilarLabs* p : labPairs) {
            SimilarCluster& c = found[groups.of(p->first)];
            c.lab = lab;
            ++c.pairs;
            c.mostAlike = std::max(c.mostAlike, p->similarity);
            for (const std::string& id : {p->first, p->second})
                if (!nearest.count(id) || nearest[id]->similarity < p->similarity) nearest[id] = p;
        }
        for (const auto& [id, pair] : nearest) // alphabetical, as the map is
            found[groups.of(id)].members.push_back({id, *pair});
        for (auto& [root, cluster] : found) clusters.push_back(std::move(cluster));
    }
    std::stable_sort(clusters.begin(), clusters.end(), [](const auto& a, const auto& b) {
        return a.mostAlike != b.mostAlike ? a.mostAlike > b.mostAlike
                                          : a.members.size() > b.members.size();
    });
    return clusters;
}

std::string sideBySidePage(const SimilarLabs& pair) {
    return "similarity/" + pair.lab + "-" + ContentHash().add(pair.first).add(pair.second).hex() +
           ".html";
}

std::string clustersHtml(const std::vector<SimilarCluster>& clusters) {
    std::ostringstream html;
    html << "<table><tr><th>lab</th><th>submissions</th><th>pairs</th><th>most alike</th>"
            "<th>each with the one it is most like (side by side)</th></tr>\n";
    for (const SimilarCluster& c : clusters) {
        html << "<tr><td>" << escapeXml(c.lab) << "</td><td>" << c.members.size() << "</td><td>"
             << c.pairs << "</td><td>" << std::lround(100 * c.mostAlike) << "%</td><td>";
        for (size_t i = 0; i < c.members.size(); ++i) {
            const SimilarCluster::Member& m = c.members[i];
            const std::string other = m.nearest.first == m.id ? m.nearest.second : m.nearest.first;
            html << (i ? "<br>" : "") << escapeXml(m.id) << " &harr; <a href=\""
                 << escapeXml(sideBySidePage(m.nearest)) << "\">" << escapeXml(other) << " ("
                 << std::lround(100 * m.nearest.similarity) << "%)</a>";
        }
        html << "</td></tr>\n";
    }
    return html.str() + "</table>\n";
}

} // namespace pathlab::grader
