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
// A crossing of a wider face between two ambiguous edges is at most this many times as long as the
// straight line across: a curve that switches edges, not one that runs along the face's middle.
constexpr double kCrossingDetour = 2.0;

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

// The B-rep faces that an ambiguous edge bounds: their boundary triangles and ambiguous edges.
struct AmbiguousFace {
    std::vector<Triangle> triangles;
    std::vector<int> edges;  // ambiguous B-rep edge ids
    bool narrow = true;      // every vertex within the strip width of those edges
};

std::map<int, AmbiguousFace> ambiguous_faces(const TetMesh& mesh, const FeatureSet& features,
                                             const std::map<int, std::vector<Segment>>& by_edge, double width) {
    std::map<int, AmbiguousFace> out;
    std::map<int, std::vector<Segment>> face_segments;  // B-rep face -> its ambiguous edges' segments
    for (const auto& [edge, segments] : by_edge)
        for (int f : features.edges[size_t(edge - 1)].faces) {
            face_segments[f].insert(face_segments[f].end(), segments.begin(), segments.end());
            out[f].edges.push_back(edge);
        }
    for (Eigen::Index b = 0; b < mesh.boundary_faces.rows(); ++b) {
        const int f = mesh.face_tags.size() > b ? mesh.face_tags(b) : 0;
        const auto it = face_segments.find(f);
        if (it == face_segments.end()) continue;
        Triangle t;
        AmbiguousFace& face = out[f];
        for (int k = 0; k < 3; ++k) {
            t[size_t(k)] = mesh.points.row(mesh.boundary_faces(b, k)).transpose();
            face.narrow = face.narrow && near_any(t[size_t(k)], it->second, width);
        }
        face.triangles.push_back(t);
    }
    return out;
}

bool near_triangles(const Vec3& p, const std::vector<Triangle>& triangles, double radius) {
    return std::any_of(triangles.begin(), triangles.end(),
                       [&](const Triangle& t) { return point_triangle_distance(p, t[0], t[1], t[2]) <= radius; });
}

// What a curve may be glued along: the ambiguous edges' segments, the strips' triangles (narrow
// faces: a curve crossing a strip from one of its edges to the other is as much the edge's as one
// along it), and the wider faces between two ambiguous edges, which a curve may only cross.
struct Glue {
    std::map<int, std::vector<Segment>> by_edge;
    std::vector<Triangle> strips;
    std::map<int, AmbiguousFace> faces;
    double radius = 0;

    // The ambiguous edge a point lies within the radius of; 0 on a strip; -1 for neither.
    int near(const Vec3& p) const {
        for (const auto& [edge, segments] : by_edge)
            if (near_any(p, segments, radius)) return edge;
        return near_triangles(p, strips, radius) ? 0 : -1;
    }

    // Points [i, j) of c, off every edge between points near edges a and b: a crossing of a face
    // bounded by both, within the strip width of it, no longer than kCrossingDetour times the
    // straight line between the two points where it leaves and reaches the edges.
    bool crosses(const SingularCurve& c, int i, int j, int a, int b) const {
        if (a < 1 || b < 1 || a == b) return false;
        const auto point = [&](int k) { return Vec3(c.points.row(k).transpose()); };
        double length = 0;
        for (int k = i; k <= j; ++k) length += (point(k) - point(k - 1)).norm();
        if (length > kCrossingDetour * (point(j) - point(i - 1)).norm()) return false;
        for (const auto& [f, face] : faces) {
            const auto has = [&](int e) { return std::count(face.edges.begin(), face.edges.end(), e) > 0; };
            if (!has(a) || !has(b)) continue;
            bool on = true;
            for (int k = i; k < j && on; ++k) on = near_triangles(point(k), face.triangles, kStripWidth * radius);
            if (on) return true;
        }
        return false;
    }
};

Glue glue_of(const TetMesh& mesh, const FeatureSet& features, double radius) {
    Glue g;
    g.by_edge = ambiguous_segments(mesh, features);
    g.radius = radius;
    g.faces = ambiguous_faces(mesh, features, g.by_edge, kStripWidth * radius);
    for (const auto& [f, face] : g.faces)
        if (face.narrow) g.strips.insert(g.strips.end(), face.triangles.begin(), face.triangles.end());
    return g;
}

// Whether every stretch of points off the edges (label 0 or -1) runs from one ambiguous edge
// across a face to another.
bool edges_or_crossings(const SingularCurve& c, const Glue& glue, const std::vector<int>& label) {
    const int n = int(label.size());
    for (int i = 0; i < n;) {
        if (label[size_t(i)] >= 1) {
            ++i;
            continue;
        }
        int j = i;
        while (j < n && label[size_t(j)] < 1) ++j;
        if (i == 0 || j == n || !glue.crosses(c, i, j, label[size_t(i - 1)], label[size_t(j)])) return false;
        i = j;
    }
    return true;
}

// Every point near an ambiguous edge or a strip; or every point near an ambiguous edge but for
// crossings of a face between two of them (on strips, those that dip deeper than the radius).
bool hugs(const SingularCurve& c, const Glue& glue) {
    const int n = int(c.points.rows());
    std::vector<int> label(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) label[size_t(i)] = glue.near(c.points.row(i).transpose());
    const bool near_all = std::all_of(label.begin(), label.end(), [](int e) { return e >= 0; });
    return n > 0 && (near_all || edges_or_crossings(c, glue, label));
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
    if (radius <= 0) return 0;
    const Glue glue = glue_of(mesh, features, radius);
    if (glue.by_edge.empty()) return 0;
    std::vector<char> glued(g.curves.size(), 0);
    for (size_t i = 0; i < g.curves.size(); ++i) glued[i] = hugs(g.curves[i], glue);
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
