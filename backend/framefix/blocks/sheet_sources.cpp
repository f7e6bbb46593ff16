#include "framefix/blocks/sheet_sources.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "framefix/frame_field/projection.h"
#include "framefix/singularities/polyline.h"
#include "framefix/streamlines/feature_seeds.h"

namespace framefix {

namespace {

// A snapped path on a surface bending away from the solid by more than this per h (radius below
// 50 h) emits no sheet: the bulge (the groove's island, a dome, a boss) is one block whose face
// the path splits, and the layers turn at the corner lines of the curtain below it
// (docs/algorithms.md#curtain-corners). On a flat or concave surface (the notch) the path's
// sheets cut the solid.
constexpr double kConvexPathBend = 0.02;

Eigen::Vector3d axis(const FrameField& field, int vert, int k) {
    return field.axes.row(vert).segment<3>(3 * k).transpose();
}

Eigen::Vector3d unit_or_zero(const Eigen::Vector3d& v) {
    const double n = v.norm();
    return n > 1e-30 ? Eigen::Vector3d(v / n) : Eigen::Vector3d::Zero();
}

// Zero crossings of the deviation angle between e_r and the closest frame axis normal to the
// curve, sampled on a circle (72 samples) around `center`.
std::vector<Eigen::Vector3d> separatrix_directions(const TetMesh& mesh, const FrameField& field,
                                                   const TetLocator& locator, const Eigen::Vector3d& center,
                                                   const Eigen::Vector3d& tangent, double radius) {
    constexpr int kSamples = 72;
    const Eigen::Vector3d e1 =
        unit_or_zero(tangent.cross(std::abs(tangent.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY()));
    const Eigen::Vector3d e2 = tangent.cross(e1);
    std::vector<double> dev(kSamples, NAN), theta(kSamples);
    int tet = -1;
    Eigen::Matrix3d warm;
    bool has_warm = false;
    for (int s = 0; s < kSamples; ++s) {
        theta[s] = 2 * M_PI * s / kSamples;
        const Eigen::Vector3d er = std::cos(theta[s]) * e1 + std::sin(theta[s]) * e2, et = tangent.cross(er);
        const TetLocation at = locator.locate(center + radius * er, tet);
        if (at.tet < 0) continue;
        tet = at.tet;
        const Eigen::Vector4d w = at.bary.cwiseMax(0.0) / at.bary.cwiseMax(0.0).sum();
        SH9 q = SH9::Zero();
        for (int lv = 0; lv < 4; ++lv) q += w[lv] * field.coefficients.row(mesh.tets(at.tet, lv)).transpose();
        const ProjectedFrame f = project_frame_from(q, has_warm ? &warm : nullptr);
        warm = f.rotation, has_warm = true;
        double best = -1;
        Eigen::Vector3d a = Eigen::Vector3d::Zero();
        for (int k = 0; k < 3; ++k) {
            const Eigen::Vector3d c = f.rotation.col(k);
            if (std::abs(c.dot(tangent)) >= 0.7) continue;  // the axis along the curve
            if (std::abs(c.dot(er)) > best) best = std::abs(c.dot(er)), a = c.dot(er) < 0 ? Eigen::Vector3d(-c) : c;
        }
        if (best >= 0) dev[s] = std::atan2(a.dot(et), a.dot(er)) * 180 / M_PI;
    }
    std::vector<Eigen::Vector3d> zeros;
    for (int s = 0; s < kSamples; ++s) {
        const double d0 = dev[s], d1 = dev[(s + 1) % kSamples];
        if (std::isnan(d0) || std::isnan(d1) || d0 * d1 > 0 || std::abs(d0 - d1) >= 45) continue;
        const double w = d0 != d1 ? d0 / (d0 - d1) : 0;
        const double t = theta[s] + w * 2 * M_PI / kSamples;
        const Eigen::Vector3d z = std::cos(t) * e1 + std::sin(t) * e2;
        bool dup = false;
        for (const auto& y : zeros) dup |= z.dot(y) >= 0.99;  // an exact zero on a sample is seen twice
        if (!dup) zeros.push_back(z);
    }
    return zeros;
}

struct BoundaryNormals {
    std::vector<Eigen::Vector3d> normal;  // outward area normal per vertex (zero inside)
    std::vector<char> on_feature;         // vertex on a feature curve
};

BoundaryNormals boundary_normals(const TetMesh& mesh, const FeatureSet& features) {
    const int nv = mesh.num_vertices();
    BoundaryNormals out{std::vector<Eigen::Vector3d>(nv, Eigen::Vector3d::Zero()), std::vector<char>(nv, 0)};
    for (int b = 0; b < int(mesh.boundary_faces.rows()); ++b) {
        const Eigen::Vector3i f = mesh.boundary_faces.row(b).transpose();
        const Eigen::Vector3d n = (mesh.points.row(f[1]) - mesh.points.row(f[0]))
                                      .cross(mesh.points.row(f[2]) - mesh.points.row(f[0]))
                                      .transpose();
        for (int k = 0; k < 3; ++k) out.normal[f[k]] += n;
    }
    for (int e = 0; e < int(mesh.feature_edges.rows()); ++e)
        if (features.valence_of(mesh.edge_tags[e]) > 0) out.on_feature[mesh.feature_edges(e, 0)] = out.on_feature[mesh.feature_edges(e, 1)] = 1;
    return out;
}

}  // namespace

bool closed_chain(const std::vector<FeatureSeed>& S) {
    if (S.size() < 4) return false;
    double step = 0;
    for (size_t i = 1; i < S.size(); ++i) step = std::max(step, (S[i].point - S[i - 1].point).norm());
    return (S.front().point - S.back().point).norm() <= 1.5 * step;
}

std::vector<char> convex_paths(const TetMesh& mesh, const FeatureSet& features, const std::vector<SnappedPath>& paths,
                               double h) {
    // Normal curvature across each path (1 / model units; > 0 convex, < 0 concave, seen from the
    // solid): at its vertices off feature curves, sum (n_q - n_v) . (q - v) / sum |q - v|^2 over the
    // boundary neighbours q off the path. One pass over the boundary faces for all paths.
    const BoundaryNormals bn = boundary_normals(mesh, features);
    std::unordered_map<int, std::vector<int>> paths_at;  // vertex -> the paths through it
    for (int pi = 0; pi < int(paths.size()); ++pi)
        for (int v : paths[pi].vertices) paths_at[v].push_back(pi);
    auto on_path = [&](int v, int pi) {
        const auto it = paths_at.find(v);
        return it != paths_at.end() && std::find(it->second.begin(), it->second.end(), pi) != it->second.end();
    };
    std::vector<double> num(paths.size(), 0), den(paths.size(), 0);
    for (int b = 0; b < int(mesh.boundary_faces.rows()); ++b)
        for (int k = 0; k < 3; ++k) {
            const int v = mesh.boundary_faces(b, k);
            const auto it = paths_at.find(v);
            if (it == paths_at.end() || bn.on_feature[v]) continue;
            for (int pi : it->second)
                for (int o = 1; o < 3; ++o) {
                    const int q = mesh.boundary_faces(b, (k + o) % 3);
                    if (on_path(q, pi)) continue;
                    const Eigen::Vector3d d = (mesh.points.row(q) - mesh.points.row(v)).transpose();
                    num[pi] += (unit_or_zero(bn.normal[q]) - unit_or_zero(bn.normal[v])).dot(d);
                    den[pi] += d.squaredNorm();
                }
        }
    std::vector<char> out(paths.size(), 0);
    for (size_t pi = 0; pi < paths.size(); ++pi) out[pi] = den[pi] > 0 && num[pi] / den[pi] * h > kConvexPathBend;
    return out;
}

std::vector<int> boundary_wisps(const SingularityGraph& graph, double h) {
    auto on_boundary = [&](int node) { return node >= 0 && node < int(graph.nodes.size()) && graph.nodes[node].boundary; };
    std::vector<int> out;
    for (const SingularCurve& c : graph.curves) {
        if (c.closed || !on_boundary(c.ends[0]) || !on_boundary(c.ends[1])) continue;
        if (polyline_length(c.points) < kWispLength_h * h) out.push_back(c.id);
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::vector<SheetSource> singular_sources(const TetMesh& mesh, const FrameField& field, const SingularityGraph& graph,
                                          const TetLocator& locator, double h, const BlockOptions& options,
                                          const std::vector<int>& skip) {
    std::vector<SheetSource> out;
    std::vector<int> degree(graph.nodes.size(), 0);  // curves ending at each node
    for (const SingularCurve& c : graph.curves)
        for (int e = 0; e < 2 && !c.closed; ++e)
            if (c.ends[e] >= 0 && c.ends[e] < int(degree.size())) ++degree[c.ends[e]];
    for (const SingularCurve& c : graph.curves) {
        if (c.kind == CurveKind::Other || c.faces.size() < 3 || c.points.rows() < 2) continue;
        if (std::binary_search(skip.begin(), skip.end(), c.id)) continue;
        const Points& P = c.points;
        const int n = int(P.rows());
        std::vector<double> arc(n, 0);
        for (int i = 1; i < n; ++i) arc[i] = arc[i - 1] + (P.row(i) - P.row(i - 1)).norm();
        const int ns = std::max(2, int(std::lround(arc.back() / (options.seed_spacing * h))) + 1);
        SheetSource src;
        src.kind = SheetSource::Singular;
        src.name = "singular:" + std::to_string(c.id);
        int last = -1;
        for (int s = 0; s < ns; ++s) {
            const double target = arc.back() * s / (ns - 1);
            const int i = std::min(int(std::lower_bound(arc.begin(), arc.end(), target) - arc.begin()), n - 1);
            if (i == last) continue;
            last = i;
            SheetSeed seed;
            seed.point = P.row(i).transpose();
            seed.tangent = unit_or_zero((P.row(std::min(i + 2, n - 1)) - P.row(std::max(i - 2, 0))).transpose());
            seed.directions = separatrix_directions(mesh, field, locator, seed.point, seed.tangent, options.seed_radius * h);
            src.seeds.push_back(std::move(seed));
        }
        src.closed = c.closed;
        for (int e = 0; e < 2; ++e)
            src.boundary_end[e] = !c.closed && c.ends[e] >= 0 && c.ends[e] < int(graph.nodes.size()) &&
                                  graph.nodes[c.ends[e]].boundary;
        for (int e = 0; e < 2; ++e)
            if (!c.closed && c.ends[e] >= 0 && c.ends[e] < int(graph.nodes.size()) &&
                !graph.nodes[c.ends[e]].boundary && degree[c.ends[e]] >= 3)
                src.junction[e] = c.ends[e];
        out.push_back(std::move(src));
    }
    return out;
}

std::vector<SheetSource> glued_sources(const TetMesh& mesh, const FrameField& field, const SingularityGraph& graph,
                                       const TetLocator& locator, double h, const BlockOptions& options) {
    SingularityGraph glued;  // the glued curves, each open one between two boundary nodes of its own
    glued.curves = graph.absorbed;
    for (SingularCurve& c : glued.curves)
        for (int e = 0; e < 2 && !c.closed && c.points.rows() > 0; ++e) {
            SingularNode n;
            n.id = int(glued.nodes.size());
            n.boundary = true;
            n.position = c.points.row(e == 0 ? 0 : c.points.rows() - 1).transpose();
            c.ends[e] = n.id;
            glued.nodes.push_back(n);
        }
    std::vector<SheetSource> out = singular_sources(mesh, field, glued, locator, h, options);
    for (size_t i = 0; i < out.size(); ++i) out[i].name = "glued:" + std::to_string(i);
    return out;
}

JunctionEnd junction_end(const SheetSource& source, int f) {
    const std::vector<SheetSeed>& T = source.seeds;
    const int n = int(T.size());
    JunctionEnd out;
    if (n < 2) return out;
    out.seed = f == 0 ? 0 : n - 1;
    for (int j = 1; j < std::min(3, n); ++j) {
        const int kj = f == 0 ? j : n - 1 - j;
        if (T[kj].directions.size() > T[out.seed].directions.size()) out.seed = kj;
    }
    out.tangent = unit_or_zero(T[f == 0 ? std::min(2, n - 1) : std::max(n - 3, 0)].point - T[f == 0 ? 0 : n - 1].point);
    return out;
}

bool straight_through(const std::vector<SheetSource>& sources, int si, int e, int sj, int f) {
    const int node = sources[si].junction[e];
    if (node < 0 || sources[sj].junction[f] != node || (si == sj && e == f)) return false;
    const JunctionEnd a = junction_end(sources[si], e), b = junction_end(sources[sj], f);
    return a.seed >= 0 && b.seed >= 0 && -a.tangent.dot(b.tangent) > kJunctionAlongCos;
}

bool has_straight_junction(const std::vector<SheetSource>& sources) {
    for (int si = 0; si < int(sources.size()); ++si)
        for (int sj = si + 1; sj < int(sources.size()); ++sj)
            for (int e = 0; e < 2; ++e)
                for (int f = 0; f < 2; ++f)
                    if (straight_through(sources, si, e, sj, f)) return true;
    return false;
}

std::vector<int> followed_imprints(const TetMesh& mesh, const FeatureSet& features, const FrameField& field) {
    // 15 deg: an arc the field follows stays within a few degrees; one it ignores deviates by up
    // to 45 deg (a quarter arc under a constant frame: 22 deg on average).
    constexpr double kFollowDeg = 15;
    std::vector<int> imprinted, out;
    for (const EdgeFeature& e : features.edges)  // a chamfer's 135 degree edge is no imprint
        if (e.valence == 2 && !ambiguous_edge(e)) imprinted.push_back(e.edge);
    for (const FeatureSeeds& curve : feature_seeds(mesh, features, field, imprinted)) {
        double sum = 0;
        int n = 0;
        for (size_t i = 1; i + 1 < curve.seeds.size(); ++i, ++n) {  // the ends take a corner's frame
            double best = 0;
            for (int k = 0; k < 3; ++k) best = std::max(best, std::abs(axis(field, curve.seeds[i].vertex, k).dot(curve.seeds[i].tangent)));
            sum += std::acos(std::min(best, 1.0)) * 180 / M_PI;
        }
        if (n > 0 && sum / n <= kFollowDeg) out.push_back(curve.edge);
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::vector<SheetSource> feature_sources(const TetMesh& mesh, const FeatureSet& features, const FrameField& field,
                                         const std::vector<FeatureSeeds>& curves, const std::vector<SnappedPath>& paths,
                                         const std::vector<char>& convex) {
    const BoundaryNormals bn = boundary_normals(mesh, features);
    const std::vector<Eigen::Vector3d>& vert_normal = bn.normal;
    const std::vector<char>& on_feature = bn.on_feature;
    std::vector<SheetSource> out;
    for (const FeatureSeeds& curve : curves) {
        SheetSource src;
        src.kind = curve.valence == 2 ? SheetSource::Imprinted : SheetSource::Concave;
        src.name = (curve.valence == 2 ? "imprinted:" : "concave:") + std::to_string(curve.edge);
        for (const FeatureSeed& f : curve.seeds) src.seeds.push_back({f.point, f.tangent, f.directions});
        src.closed = closed_chain(curve.seeds);
        src.boundary_end[0] = src.boundary_end[1] = !src.closed;
        out.push_back(std::move(src));
    }

    for (size_t pi = 0; pi < paths.size(); ++pi) {
        const std::vector<int>& V = paths[pi].vertices;
        const int m = int(V.size());
        if (m < 2 || convex[pi]) continue;
        SheetSource src;
        src.kind = SheetSource::Snapped;
        src.name = "snapped:" + std::to_string(pi);
        src.boundary_end[0] = src.boundary_end[1] = true;
        for (int i = 0; i < m; ++i) {
            const int v = V[i];
            // An end on a feature curve has the normal of neither face: use its path neighbour's.
            const int nvert = on_feature[v] ? V[i == 0 ? 1 : (i == m - 1 ? m - 2 : i)] : v;
            const Eigen::Vector3d n = unit_or_zero(vert_normal[nvert]);
            SheetSeed seed;
            seed.point = mesh.points.row(v).transpose();
            seed.tangent = unit_or_zero((mesh.points.row(V[std::min(i + 1, m - 1)]) -
                                         mesh.points.row(V[std::max(i - 1, 0)])).transpose());
            for (int k = 0; k < 3; ++k) {
                const Eigen::Vector3d a = axis(field, v, k);
                if (std::abs(a.dot(n)) > 0.3) seed.directions.push_back(a.dot(n) > 0 ? Eigen::Vector3d(-a) : a);
            }
            src.seeds.push_back(std::move(seed));
        }
        out.push_back(std::move(src));
    }
    return out;
}

}  // namespace framefix
