// Feature chains and the interpolation of their Dirichlet frames between snapped points.
#include "framefix/corrections/split_curves.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "framefix/core/error.h"
#include "framefix/frame_field/projection.h"

namespace framefix {

namespace {

FeatureChain order_chain(int tag, const std::vector<std::pair<int, int>>& edges) {
    std::map<int, std::vector<int>> adjacency;
    for (const auto& [a, b] : edges) adjacency[a].push_back(b), adjacency[b].push_back(a);
    FeatureChain chain;
    chain.tag = tag;
    int start = edges.front().first;
    for (const auto& [v, nbrs] : adjacency)
        if (nbrs.size() == 1) {
            start = v;
            break;
        }
    chain.closed = adjacency.at(start).size() != 1;
    chain.vertices.push_back(start);
    int prev = -1, cur = start;
    // Bounded walk: a branching tag (not a simple curve) still terminates.
    for (size_t step = 0; step <= edges.size(); ++step) {
        const std::vector<int>& nbrs = adjacency.at(cur);
        int next = -1;
        for (int w : nbrs)
            if (w != prev) {
                next = w;
                break;
            }
        if (next < 0) break;
        chain.vertices.push_back(next);
        if (next == start) break;
        prev = cur, cur = next;
    }
    return chain;
}

std::vector<double> arc_lengths(const Points& points, const std::vector<int>& chain) {
    std::vector<double> s(chain.size(), 0.0);
    for (size_t k = 1; k < chain.size(); ++k) s[k] = s[k - 1] + (points.row(chain[k]) - points.row(chain[k - 1])).norm();
    return s;
}

bool is_fixed(const Constraints& c, int v) { return c.kind[v] == ConstraintKind::Fixed; }

// Angle between two frames modulo the cube group, degrees.
double frame_angle_deg(const SH9& qa, const SH9& qb) {
    const Eigen::Matrix3d Ra = project_frame(qa).rotation;
    const Eigen::Matrix3d Rb = match_frame(Ra, project_frame(qb).rotation);
    return std::acos(std::clamp(((Ra.transpose() * Rb).trace() - 1) / 2, -1.0, 1.0)) * 180.0 / M_PI;
}

}  // namespace

std::vector<FeatureChain> feature_chains(const TetMesh& mesh, const FeatureSet& features) {
    std::map<int, std::vector<std::pair<int, int>>> by_tag;
    const bool tagged = mesh.edge_tags.size() == mesh.feature_edges.rows();
    for (int e = 0; e < mesh.feature_edges.rows(); ++e) {
        const int tag = tagged ? mesh.edge_tags(e) : 0;
        if (tagged && !features.edges.empty() && features.valence_of(tag) == 0) continue;
        by_tag[tag].emplace_back(mesh.feature_edges(e, 0), mesh.feature_edges(e, 1));
    }
    std::vector<FeatureChain> chains;
    for (const auto& [tag, edges] : by_tag) chains.push_back(order_chain(tag, edges));
    return chains;
}

std::vector<std::pair<int, SH9>> interpolate_split_curves(const Points& points, const std::vector<FeatureChain>& chains,
                                                          const Constraints& original,
                                                          const std::map<int, SH9>& anchors,
                                                          const std::set<int>& collapsed) {
    std::vector<std::pair<int, SH9>> result;
    for (const FeatureChain& ch0 : chains) {
        std::vector<int> ch = ch0.vertices;
        auto first_anchor = std::find_if(ch.begin(), ch.end(), [&](int v) { return anchors.count(v) > 0; });
        const bool has_collapsed = std::any_of(ch.begin(), ch.end(), [&](int v) { return collapsed.count(v) > 0; });
        if (first_anchor == ch.end() && !has_collapsed) continue;
        const bool cyclic = ch0.closed && !is_fixed(original, ch.front());
        if (cyclic) {
            if (first_anchor == ch.end()) continue;  // a smooth loop with no S point has no anchor at all
            // Start and end the loop at an S point so that the S points are its only anchors.
            std::vector<int> loop(ch.begin(), ch.end() - 1);
            std::rotate(loop.begin(), loop.begin() + (first_anchor - ch.begin()), loop.end());
            loop.push_back(loop.front());
            ch = loop;
        }
        std::map<int, SH9> anchor_at;  // chain index -> frame
        const int last = int(ch.size()) - 1;
        if (!cyclic && last >= 1) {
            // An end vertex that is not Dirichlet (free corner), or whose corner frame is more than
            // 25 deg from the curve's own frames (seen on an imprinted arc meeting a box edge: the
            // polar factor of two equal normals is 45 deg off), borrows its neighbour's frame.
            for (const auto& [k, nbr] : {std::pair<int, int>{0, 1}, std::pair<int, int>{last, last - 1}}) {
                const bool use_end = is_fixed(original, ch[k]) &&
                                     (!is_fixed(original, ch[nbr]) ||
                                      frame_angle_deg(original.fixed.row(ch[k]).transpose(),
                                                      original.fixed.row(ch[nbr]).transpose()) < 25);
                const int v = use_end ? ch[k] : ch[nbr];
                if (is_fixed(original, v)) anchor_at[k] = original.fixed.row(v).transpose();
            }
        }
        for (int k = 0; k <= last; ++k)
            if (anchors.count(ch[k])) anchor_at[k] = anchors.at(ch[k]);

        if (anchor_at.size() < 2) continue;
        const std::vector<double> s = arc_lengths(points, ch);
        for (auto a = anchor_at.begin(), b = std::next(a); b != anchor_at.end(); ++a, ++b) {
            const double span = std::max(s[b->first] - s[a->first], 1e-300);
            for (int k = a->first; k <= b->first; ++k) {
                const int v = ch[k];
                if (!(cyclic || is_fixed(original, v) || anchors.count(v))) continue;
                if (!anchors.count(v) && (k == a->first || k == b->first)) continue;  // keeps its own frame
                const double w = (s[k] - s[a->first]) / span;
                const ProjectedFrame f = project_frame((1 - w) * a->second + w * b->second);
                // Anchors 45 deg apart can cancel at mid-span; then keep the nearer anchor.
                result.emplace_back(v, f.defined ? f.q : (w < 0.5 ? a->second : b->second));
            }
        }
    }
    return result;
}

}  // namespace framefix
