#include "framefix/singularities/singularity_graph.h"

#include <array>
#include <chrono>
#include <vector>

#include "framefix/core/error.h"
#include "framefix/singularities/chain_ends.h"
#include "framefix/singularities/chains.h"
#include "framefix/singularities/curve_labels.h"
#include "framefix/singularities/edge_chains.h"
#include "framefix/singularities/edge_holonomy.h"
#include "framefix/singularities/holonomy.h"
#include "framefix/singularities/node_validity.h"
#include "framefix/singularities/polyline.h"
#include "framefix/singularities/three_five.h"

namespace framefix {
namespace {

using Axes = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

// Labels of the elements curves are made of (triangles or edges) and the chains through them.
struct Labelled {
    std::vector<int> valence;
    Axes axis;
    ChainGraph chains;
    int subsampled_edges = 0;
};

Labelled label_and_chain(const TetMesh& mesh, const TetTopology& topo, const FrameField& field,
                         const SingularityOptions& options) {
    ChainOptions co;
    co.attach_distance = options.attach_distance;
    Labelled out;
    if (options.holonomy == Holonomy::Edges) {
        EdgeHolonomy h = edge_holonomy(mesh, topo, field, options.threads);
        out.chains = trace_edge_chains(mesh, topo, h.valence, h.axis, co);
        label_edges_along_curves(mesh, topo, out.chains, h.axis, h.valence);
        out.valence = std::move(h.valence);
        out.axis = std::move(h.axis);
        return out;
    }
    HolonomyOptions ho;
    ho.direct_match_deg = options.direct_match_deg;
    ho.threads = options.threads;
    FaceHolonomy h = face_holonomy(mesh, topo, field, ho);
    out.chains = trace_chains(mesh, topo, h.valence, co);
    if (options.labels_along_curves) label_faces_along_curves(mesh, topo, out.chains, h.axis, h.valence);
    out.valence = std::move(h.valence);
    out.axis = std::move(h.axis);
    out.subsampled_edges = h.subsampled_edges;
    return out;
}

Eigen::Vector3d element_position(const TetMesh& mesh, const TetTopology& topo, Holonomy kind, int i) {
    if (kind == Holonomy::Triangles) return detail::face_centroid(mesh, topo, i);
    return (mesh.points.row(topo.edges(i, 0)) + mesh.points.row(topo.edges(i, 1))).transpose() / 2;
}

void check_options(const SingularityOptions& o) {
    if (o.majority_window < 1)
        throw Error("singularities", "majority_window is " + std::to_string(o.majority_window) + "; use 1 or more (5)");
    if (o.smoothing_passes < 0)
        throw Error("singularities", "smoothing_passes is " + std::to_string(o.smoothing_passes) + "; use 0 or more");
    if (!(o.direct_match_deg >= 0 && o.direct_match_deg < 45))
        throw Error("singularities", "direct_match_deg is " + std::to_string(o.direct_match_deg) +
                                         "; use 0..25 degrees (matching is ambiguous at 45)");
    if (!(o.attach_distance >= 0))
        throw Error("singularities", "attach_distance must be >= 0 mean edge lengths (3)");
    if (!(o.node_core >= 0)) throw Error("singularities", "node_core must be >= 0 mean edge lengths (1.5)");
    if (!(o.absorb_radius >= 0)) throw Error("singularities", "absorb_radius must be >= 0 mean edge lengths (1.5)");
}

// How many triangles at each end of an open curve lie in the core of a junction node (within
// node_core mean edge lengths of it): their holonomy mixes the node's curves, so they do not
// vote on the curve's valence. At least half of the curve always votes.
std::array<int, 2> core_triangles(const ChainCurve& c, const ChainGraph& g, const TetMesh& mesh, const TetTopology& topo,
                                  Holonomy kind, double radius) {
    std::array<int, 2> core{0, 0};
    if (c.closed) return core;
    const int n = int(c.faces.size());
    for (int k = 0; k < 2; ++k) {
        const ChainNode& node = g.nodes[size_t(c.ends[k])];
        if (node.boundary || node.tets.empty()) continue;
        for (int i = 0; i < n; ++i) {
            const int f = c.faces[size_t(k == 0 ? i : n - 1 - i)];
            if ((element_position(mesh, topo, kind, f) - node.position).norm() > radius) break;
            ++core[size_t(k)];
        }
    }
    if (2 * (core[0] + core[1]) > n) core = {0, 0};
    return core;
}

// The label of the boundary triangle where an open curve of triangles ends, for each end (0
// where it does not end on one): the surface singularity there fixes the curve's valence at
// that end (docs/algorithms.md#3-5-detection).
std::array<int, 2> surface_end_labels(const ChainCurve& c, const Labelled& h, const TetTopology& topo,
                                      const SingularityOptions& o) {
    std::array<int, 2> out{0, 0};
    if (c.closed || o.holonomy != Holonomy::Triangles || !o.surface_end_labels) return out;
    for (int k = 0; k < 2; ++k) {
        const int f = k == 0 ? c.faces.front() : c.faces.back();
        if (topo.face_tets(f, 0) < 0 || topo.face_tets(f, 1) < 0) out[size_t(k)] = h.valence[size_t(f)];
    }
    return out;
}

SingularCurve make_curve(const ChainCurve& c, const Labelled& h, const SingularityOptions& o,
                         const std::array<int, 2>& core, const std::array<int, 2>& forced) {
    SingularCurve out;
    out.faces = c.faces;
    out.closed = c.closed;
    out.ends[0] = c.ends[0];
    out.ends[1] = c.ends[1];
    std::vector<Eigen::Vector3d> axes;
    for (int f : c.faces) {
        out.valences.push_back(h.valence[f]);
        axes.push_back(h.axis.row(f).transpose());
    }
    const std::vector<int> voting(out.valences.begin() + core[0], out.valences.end() - core[1]);
    const LabelClass lc = classify_labels(voting, c.closed, o.majority_window, forced.data());
    out.kind = lc.kind;
    out.end_valence[0] = lc.end_label[0];
    out.end_valence[1] = lc.end_label[1];
    if (lc.transition >= 0) out.transition = c.face_point[size_t(lc.transition + core[0])];
    out.stable_direction = mean_axis(axes);
    out.points = smooth_polyline(c.points, c.closed, o.smoothing_passes);
    out.length = polyline_length(out.points);
    return out;
}

SingularCurve curve_of(const ChainGraph& g, int i, const Labelled& h, const TetMesh& mesh, const TetTopology& topo,
                       const SingularityOptions& o) {
    const ChainCurve& c = g.curves[size_t(i)];
    return make_curve(c, h, o, core_triangles(c, g, mesh, topo, o.holonomy, o.node_core * g.h_mean),
                      surface_end_labels(c, h, topo, o));
}

bool pure(const SingularCurve& c) { return c.kind == CurveKind::Valence3 || c.kind == CurveKind::Valence5; }

// A crossing joins two pure curves into a valid node of pure pieces
// (docs/algorithms.md#crossings-near-the-boundary): it never splits a 3-5 curve, so it cannot
// hide one behind a node.
int join_pure_crossings(Labelled& h, const TetMesh& mesh, const TetTopology& topo, const SingularityOptions& o) {
    auto accept = [&](const ChainGraph& before, const ChainGraph& after, int a, int b, int node) {
        if (!pure(curve_of(before, a, h, mesh, topo, o)) || !pure(curve_of(before, b, h, mesh, topo, o))) return false;
        std::vector<int> pieces{a, b};
        for (int i = int(before.curves.size()); i < int(after.curves.size()); ++i) pieces.push_back(i);
        int n3 = 0, n5 = 0;
        for (int i : pieces) {
            const SingularCurve c = curve_of(after, i, h, mesh, topo, o);
            if (!pure(c)) return false;
            for (int k = 0; k < 2; ++k)
                if (c.ends[k] == node) (c.end_valence[k] == 3 ? n3 : n5) += 1;
        }
        return is_valid_interior_node(n3, n5);
    };
    return detail::join_crossings(h.chains, topo, accept);
}

}  // namespace

const char* to_string(CurveKind kind) {
    switch (kind) {
        case CurveKind::Valence3: return "valence3";
        case CurveKind::Valence5: return "valence5";
        case CurveKind::ThreeFive: return "3-5";
        case CurveKind::Other: return "other";
    }
    return "other";
}

void count_summary(SingularityGraph& g) {
    SingularitySummary& s = g.summary;
    s.curves = int(g.curves.size());
    s.valence3 = s.valence5 = s.curves_3_5 = s.mixed_loops = 0;
    for (const SingularCurve& c : g.curves) {
        s.valence3 += c.kind == CurveKind::Valence3;
        s.valence5 += c.kind == CurveKind::Valence5;
        s.curves_3_5 += c.kind == CurveKind::ThreeFive;
        s.mixed_loops += c.kind == CurveKind::Other;
    }
    s.nodes = int(g.nodes.size());
    s.invalid_nodes = 0;
    for (const SingularNode& n : g.nodes) s.invalid_nodes += !n.valid;
    s.meshable = s.curves_3_5 == 0 && s.invalid_nodes == 0;
}

SingularityGraph extract_singularities(const TetMesh& mesh, const TetTopology& topo, const FrameField& field,
                                       const SingularityOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    check_options(options);
    Labelled h = label_and_chain(mesh, topo, field, options);
    if (options.holonomy == Holonomy::Triangles && options.join_crossings)
        h.chains.crossings = join_pure_crossings(h, mesh, topo, options);
    const ChainGraph& chains = h.chains;

    SingularityGraph g;
    g.h_mean = chains.h_mean;
    g.subsampled_edges = h.subsampled_edges;
    g.dead_ends = chains.dead_ends;
    g.dead_ends_attached = chains.dead_ends_attached;
    g.junk_chains = chains.junk_chains;
    g.joined = chains.joined;
    g.crossings = chains.crossings;
    for (size_t i = 0; i < chains.curves.size(); ++i) {
        const ChainCurve& c = chains.curves[i];
        const double core_radius = options.node_core * chains.h_mean;
        g.curves.push_back(make_curve(c, h, options, core_triangles(c, chains, mesh, topo, options.holonomy, core_radius),
                                      surface_end_labels(c, h, topo, options)));
        g.curves.back().id = int(i);
    }

    const std::vector<char> feature = feature_vertices(mesh);
    for (size_t i = 0; i < chains.nodes.size(); ++i) {
        const ChainNode& cn = chains.nodes[i];
        SingularNode n;
        n.id = int(i);
        n.position = cn.position;
        n.boundary = cn.boundary;
        n.n_complex = cn.n_complex;
        n.tets = cn.tets;
        n.crossing = cn.crossing;
        g.nodes.push_back(n);
    }
    // A curve passing through a node counts twice, a curve from a node back to it too (docs/algorithms.md#3-5-detection).
    for (const SingularCurve& c : g.curves)
        if (!c.closed)
            for (int k = 0; k < 2; ++k) (c.end_valence[k] == 3 ? g.nodes[c.ends[k]].n3 : g.nodes[c.ends[k]].n5) += 1;
    for (size_t i = 0; i < g.nodes.size(); ++i) {
        SingularNode& n = g.nodes[i];
        const ChainNode& cn = chains.nodes[i];
        if (!n.boundary) {
            n.valid = is_valid_interior_node(n.n3, n.n5);
            continue;
        }
        bool on_feature = false;
        for (int v : cn.verts) on_feature |= feature[v] != 0;
        const bool axes_ok = options.holonomy == Holonomy::Edges ? cn.axes_normal
                                                                  : axes_along_normals(mesh, topo, h.axis, cn.boundary_faces);
        n.valid = on_feature || (is_valid_smooth_boundary_node(n.n3, n.n5) && axes_ok);
    }

    count_summary(g);
    SingularitySummary& s = g.summary;
    for (int v : h.valence) {
        s.singular_faces += v != 0;
        s.complex_faces += v == -1;
    }
    g.face_valence = std::move(h.valence);
    g.face_axis = std::move(h.axis);
    g.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return g;
}

}  // namespace framefix
