// Curves glued to ambiguous feature curves (docs/algorithms.md#curves-along-ambiguous-edges).
#include "framefix/singularities/edge_absorption.h"

#include <algorithm>
#include <array>
#include <map>

#include "framefix/core/segment_distance.h"
#include "framefix/singularities/node_validity.h"

namespace framefix {

namespace {

using Vec3 = Eigen::Vector3d;

// A strip is at most this many glue radii wide (about 3 h): a chamfer whose middle is farther from
// both its edges than a curve can be glued to one (docs/algorithms.md#curves-along-ambiguous-edges).
constexpr double kStripWidth = 2.0;

using Segment = std::array<Vec3, 2>;
using Triangle = std::array<Vec3, 3>;

// Mesh segments of every ambiguous feature curve, by B-rep edge id.
std::map<int, std::vector<Segment>> ambiguous_segments(const TetMesh& mesh, const FeatureSet& features) {
    std::map<int, std::vector<Segment>> out;
    for (int e = 0; e < mesh.feature_edges.rows(); ++e) {
        const int tag = mesh.edge_tags.size() > e ? mesh.edge_tags(e) : 0;
        if (tag < 1 || tag > int(features.edges.size()) || !ambiguous_edge(features.edges[size_t(tag - 1)])) continue;
        out[tag].push_back({Vec3(mesh.points.row(mesh.feature_edges(e, 0))), Vec3(mesh.points.row(mesh.feature_edges(e, 1)))});
    }
    return out;
}

bool near_any(const Vec3& p, const std::vector<Segment>& segments, double radius) {
    return std::any_of(segments.begin(), segments.end(),
                       [&](const Segment& s) { return point_segment_distance(p, s[0], s[1]) <= radius; });
}

// Boundary triangles of the strips: B-rep faces every vertex of which lies within `width` of the
// face's own ambiguous edges (a chamfer a few h wide). A curve crossing such a strip from one of
// its edges to the other is as much the edge's as one along it.
std::vector<Triangle> strip_triangles(const TetMesh& mesh, const FeatureSet& features,
                                      const std::map<int, std::vector<Segment>>& by_edge, double width) {
    std::map<int, std::vector<Segment>> face_segments;  // B-rep face -> its ambiguous edges' segments
    for (const auto& [edge, segments] : by_edge)
        for (int f : features.edges[size_t(edge - 1)].faces)
            face_segments[f].insert(face_segments[f].end(), segments.begin(), segments.end());
    std::map<int, std::vector<Triangle>> by_face;
    std::map<int, bool> narrow;
    for (Eigen::Index b = 0; b < mesh.boundary_faces.rows(); ++b) {
        const int f = mesh.face_tags.size() > b ? mesh.face_tags(b) : 0;
        const auto it = face_segments.find(f);
        if (it == face_segments.end()) continue;
        Triangle t;
        bool all_near = true;
        for (int k = 0; k < 3; ++k) {
            t[size_t(k)] = mesh.points.row(mesh.boundary_faces(b, k)).transpose();
            all_near = all_near && near_any(t[size_t(k)], it->second, width);
        }
        narrow.emplace(f, true).first->second &= all_near;
        by_face[f].push_back(t);
    }
    std::vector<Triangle> out;
    for (const auto& [f, triangles] : by_face)
        if (narrow[f]) out.insert(out.end(), triangles.begin(), triangles.end());
    return out;
}

bool hugs(const SingularCurve& c, const std::vector<Segment>& segments, const std::vector<Triangle>& strips,
          double radius) {
    for (int i = 0; i < c.points.rows(); ++i) {
        const Vec3 p = c.points.row(i).transpose();
        const bool near = near_any(p, segments, radius) || std::any_of(strips.begin(), strips.end(), [&](const Triangle& t) {
            return point_triangle_distance(p, t[0], t[1], t[2]) <= radius;
        });
        if (!near) return false;
    }
    return c.points.rows() > 0;
}

// Drops the nodes no remaining curve ends at, renumbers the rest, and counts their curve ends
// again. An interior node is judged again by the table; a boundary node keeps its verdict (its
// check needs the holonomy axes, and a node that stays has kept a curve of its own). A node a
// glued curve ended at lies within the glue radius of an ambiguous edge: it is a node on that
// feature curve, which the boundary rule does not check (n08o: the axis curve stops 2 h under
// the apex, where the glued curves along the five edges met it).
void prune_nodes(SingularityGraph& g, const std::vector<char>& on_edge) {
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
        if (on_edge[i]) n.boundary = n.valid = true;
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
    const std::map<int, std::vector<Segment>> by_edge = ambiguous_segments(mesh, features);
    if (by_edge.empty() || radius <= 0) return 0;
    std::vector<Segment> segments;
    for (const auto& [edge, s] : by_edge) segments.insert(segments.end(), s.begin(), s.end());
    const std::vector<Triangle> strips = strip_triangles(mesh, features, by_edge, kStripWidth * radius);
    std::vector<char> glued(g.curves.size(), 0);
    for (size_t i = 0; i < g.curves.size(); ++i) glued[i] = hugs(g.curves[i], segments, strips, radius);
    const int moved = int(std::count(glued.begin(), glued.end(), 1));
    if (moved == 0) return 0;
    std::vector<SingularCurve> kept;
    std::vector<char> on_edge(g.nodes.size(), 0);
    for (size_t i = 0; i < g.curves.size(); ++i) {
        SingularCurve& c = g.curves[i];
        if (glued[i])
            for (int& e : c.ends) {
                if (e >= 0) on_edge[size_t(e)] = 1;
                e = -1;
            }
        (glued[i] ? g.absorbed : kept).push_back(std::move(c));
    }
    g.curves = std::move(kept);
    for (size_t i = 0; i < g.curves.size(); ++i) g.curves[i].id = int(i);
    prune_nodes(g, on_edge);
    count_summary(g);
    return moved;
}

}  // namespace framefix
