// Curves glued to ambiguous feature curves (docs/algorithms.md#curves-along-ambiguous-edges).
#include "framefix/singularities/edge_absorption.h"

#include <algorithm>

#include "framefix/core/segment_distance.h"
#include "framefix/singularities/node_validity.h"

namespace framefix {

namespace {

using Vec3 = Eigen::Vector3d;

bool hugs(const SingularCurve& c, const std::vector<std::array<Vec3, 2>>& segments, double radius) {
    for (int i = 0; i < c.points.rows(); ++i) {
        const Vec3 p = c.points.row(i).transpose();
        const bool near = std::any_of(segments.begin(), segments.end(), [&](const auto& s) {
            return point_segment_distance(p, s[0], s[1]) <= radius;
        });
        if (!near) return false;
    }
    return c.points.rows() > 0;
}

// Drops the nodes no remaining curve ends at, renumbers the rest, and counts their curve ends
// again. An interior node is judged again by the table; a boundary node keeps its verdict (its
// check needs the holonomy axes, and a node that stays has kept a curve of its own).
void prune_nodes(SingularityGraph& g) {
    std::vector<int> n3(g.nodes.size(), 0), n5(g.nodes.size(), 0), used(g.nodes.size(), 0);
    for (const SingularCurve& c : g.curves)
        if (!c.closed)
            for (int k = 0; k < 2; ++k) {
                used[size_t(c.ends[k])] = 1;
                (c.end_valence[k] == 3 ? n3 : n5)[size_t(c.ends[k])] += 1;
            }
    std::vector<int> new_id(g.nodes.size(), -1);
    std::vector<SingularNode> kept;
    for (size_t i = 0; i < g.nodes.size(); ++i) {
        if (!used[i]) continue;
        SingularNode n = g.nodes[i];
        new_id[i] = int(kept.size());
        n.id = new_id[i];
        n.n3 = n3[i];
        n.n5 = n5[i];
        if (!n.boundary) n.valid = is_valid_interior_node(n.n3, n.n5);
        kept.push_back(std::move(n));
    }
    g.nodes = std::move(kept);
    for (SingularCurve& c : g.curves)
        if (!c.closed)
            for (int& e : c.ends) e = new_id[size_t(e)];
}

}  // namespace

int absorb_edge_curves(SingularityGraph& g, const TetMesh& mesh, const FeatureSet& features, double radius) {
    std::vector<std::array<Vec3, 2>> segments;
    for (int e = 0; e < mesh.feature_edges.rows(); ++e) {
        const int tag = mesh.edge_tags.size() > e ? mesh.edge_tags(e) : 0;
        if (tag < 1 || tag > int(features.edges.size()) || !ambiguous_edge(features.edges[size_t(tag - 1)])) continue;
        segments.push_back({Vec3(mesh.points.row(mesh.feature_edges(e, 0))), Vec3(mesh.points.row(mesh.feature_edges(e, 1)))});
    }
    if (segments.empty() || radius <= 0) return 0;
    std::vector<char> glued(g.curves.size(), 0);
    for (size_t i = 0; i < g.curves.size(); ++i) glued[i] = hugs(g.curves[i], segments, radius);
    const int moved = int(std::count(glued.begin(), glued.end(), 1));
    if (moved == 0) return 0;
    std::vector<SingularCurve> kept;
    for (size_t i = 0; i < g.curves.size(); ++i) {
        SingularCurve& c = g.curves[i];
        if (glued[i]) c.ends[0] = c.ends[1] = -1;
        (glued[i] ? g.absorbed : kept).push_back(std::move(c));
    }
    g.curves = std::move(kept);
    for (size_t i = 0; i < g.curves.size(); ++i) g.curves[i].id = int(i);
    prune_nodes(g);
    count_summary(g);
    return moved;
}

}  // namespace framefix
