#include <algorithm>
#include <chrono>
#include <unordered_map>

#include <Eigen/Geometry>

#include "framefix/core/error.h"
#include "framefix/hexmesh/flat_refinement.h"
#include "framefix/hexmesh/hex_grid.h"
#include "framefix/hexmesh/hex_projection.h"
#include "framefix/mesh/keys.h"

namespace framefix {

namespace {


std::array<Eigen::Vector3d, 8> corners_of(const HexMesh& m, const std::array<int, 8>& h) {
    std::array<Eigen::Vector3d, 8> p;
    for (int c = 0; c < 8; ++c) p[c] = m.points.row(h[c]).transpose();
    return p;
}

// The hexes of each block grid; HexBlockStats' scaled Jacobians come in measure().
void add_hexes(const HexGrid& g, const BlockComplex& cx, HexMesh& out) {
    for (size_t b = 0; b < g.block_ids.size(); ++b) {
        const HexGrid::BlockGrid& bg = g.block_ids[b];
        HexBlockStats stats;
        stats.counts = bg.n;
        for (int k = 0; k < bg.n[2]; ++k)
            for (int j = 0; j < bg.n[1]; ++j)
                for (int i = 0; i < bg.n[0]; ++i) {
                    out.hexes.push_back(hex_of(bg, i, j, k));
                    out.hex_block.push_back(int(b));
                    stats.hexes += 1;
                }
        out.blocks.push_back(stats);
    }
    for (int& b : out.hex_block) b = cx.blocks[size_t(b)].id;
}

// Each boundary face's grid quads, turned outward, with the B-rep face under each.
void add_boundary_quads(const TetMesh& mesh, const BlockComplex& cx, const HexGrid& g, HexMesh& out) {
    const SurfaceLocator locator(mesh);
    for (size_t f = 0; f < cx.faces.size(); ++f) {
        if (!cx.faces[f].boundary) continue;
        const FaceProjector onto(mesh, cx.faces[f], locator);
        const HexGrid::FaceGrid& fg = g.face_ids[f];
        std::vector<std::array<int, 4>> quads;
        std::vector<int> tags;
        double agree = 0;
        for (int t = 0; t < fg.nt; ++t)
            for (int s = 0; s < fg.ns; ++s) {
                const std::array<int, 4> q{fg.at(s, t), fg.at(s + 1, t), fg.at(s + 1, t + 1), fg.at(s, t + 1)};
                Eigen::Vector3d c = Eigen::Vector3d::Zero();
                for (int v : q) c += out.points.row(v).transpose() / 4;
                const Eigen::Vector3d n = (out.points.row(q[2]) - out.points.row(q[0])).transpose().cross(
                    (out.points.row(q[3]) - out.points.row(q[1])).transpose());
                int tag = 0;
                Eigen::Vector3d outward = Eigen::Vector3d::Zero();
                onto.project(c, {}, &tag, &outward);
                agree += n.dot(outward);
                quads.push_back(q), tags.push_back(tag);
            }
        for (auto& q : quads)
            if (agree < 0) std::swap(q[1], q[3]);
        out.boundary_quads.insert(out.boundary_quads.end(), quads.begin(), quads.end());
        out.quad_face.insert(out.quad_face.end(), tags.begin(), tags.end());
    }
}

// Order 2: one vertex at the middle of every hex edge, on the B-rep face (or curve) under it.
void add_midpoints(const TetMesh& mesh, const BlockComplex& cx, const HexGrid& g, const CadProjector& cad, HexMesh& out) {
    const std::uint64_t nv = out.points.rows();
    std::unordered_map<PairKey, int> mid;
    std::vector<Eigen::Vector3d> extra;
    auto midpoint = [&](int a, int b) {
        auto [it, fresh] = mid.try_emplace(edge_key(a, b, nv), int(nv + extra.size()));
        if (fresh) extra.push_back((out.points.row(a) + out.points.row(b)).transpose() / 2);
        return it->second;
    };
    for (const auto& h : out.hexes) {
        std::array<int, 12> m{};
        for (int e = 0; e < 12; ++e) m[e] = midpoint(h[kHexEdges[e][0]], h[kHexEdges[e][1]]);
        out.midpoints.push_back(m);
    }
    for (size_t q = 0; q < out.boundary_quads.size(); ++q)
        for (int e = 0; e < 4 && out.quad_face[q] > 0 && cad.to_face; ++e) {
            const int id = mid.at(edge_key(out.boundary_quads[q][e], out.boundary_quads[q][(e + 1) % 4], nv));
            extra[size_t(id) - nv] = cad.to_face(out.quad_face[q], extra[size_t(id) - nv]);
        }
    const SurfaceLocator locator(mesh);
    for (size_t e = 0; e < cx.edges.size(); ++e) {
        const EdgeSupport support = edge_support(mesh, cx.edges[e], locator);
        if (support.kind != EdgeSupport::curve) continue;
        for (size_t i = 0; i + 1 < g.edge_ids[e].size(); ++i) {
            const int id = mid.at(edge_key(g.edge_ids[e][i], g.edge_ids[e][i + 1], nv));
            extra[size_t(id) - nv] = project_on_support(extra[size_t(id) - nv], support, cad);
        }
    }
    out.points.conservativeResize(Eigen::Index(nv + extra.size()), 3);
    for (size_t i = 0; i < extra.size(); ++i) out.points.row(Eigen::Index(nv + i)) = extra[i].transpose();
}

// Scaled Jacobians per hex and per block, and the mesh's quality figures. `block_of`: the
// complex block (index into out.blocks) of each hex.
void measure(const std::vector<int>& block_of, HexMesh& out) {
    HexQuality& q = out.quality;
    q.min_scaled_jacobian = out.hexes.empty() ? 0 : 1;
    for (HexBlockStats& b : out.blocks) b.min_scaled_jacobian = 1;
    int good = 0;
    out.scaled_jacobian.clear();
    for (size_t h = 0; h < out.hexes.size(); ++h) {
        const double sj = hex_scaled_jacobian(corners_of(out, out.hexes[h]));
        out.scaled_jacobian.push_back(sj);
        HexBlockStats& b = out.blocks[size_t(block_of[h])];
        b.min_scaled_jacobian = std::min(b.min_scaled_jacobian, sj);
        q.min_scaled_jacobian = std::min(q.min_scaled_jacobian, sj);
        q.mean_scaled_jacobian += sj / double(out.hexes.size());
        good += sj >= 0.5;
        q.inverted += sj <= 0;
        q.volume += hex_volume(corners_of(out, out.hexes[h]));
    }
    q.share_sj_ge_0_5 = out.hexes.empty() ? 0 : double(good) / double(out.hexes.size());
}

// Directions along block edges are read this many tet edges from the corner: past the tet-edge
// staircase of the chains (about h / 2 deep), before a curved edge turns.
constexpr double kFlatReachInH = 2.0;
// A block edge is refined when its two other edges leave one of its ends more than 180 minus
// kRefineCandidateDeg apart (130 degrees) and the other end more than 180 minus kRefineEndDeg
// (90 degrees). A hex corner of angle a has a scaled Jacobian of at most sin a, so the two
// corners of about a / 2 the template makes are better from about 120 degrees on; the ends of
// one block edge differ, though: on notch_wide at 0.7 x the edge under the arc reads 153
// degrees at its top and 102 at its bottom, where its hexes fell to 0.05. Whether the refined
// mesh is kept is decided on the hexes themselves.
constexpr double kRefineCandidateDeg = 50;
constexpr double kRefineEndDeg = 90;

// The hex mesh of a complex, or done = false with the reason.
HexMesh mesh_complex(const TetMesh& mesh, BlockComplex cx, double size, const HexMeshOptions& options,
                     const CadProjector& cad) {
    HexMesh out;
    out.edge_classes = assign_edge_counts(cx, size, options.layers);
    out.size = size;
    HexGrid g = hex_grid(mesh, cx, cad);
    out.points.resize(Eigen::Index(g.points.size()), 3);
    for (size_t i = 0; i < g.points.size(); ++i) out.points.row(Eigen::Index(i)) = g.points[i].transpose();
    add_hexes(g, cx, out);
    add_boundary_quads(mesh, cx, g, out);
    smooth_hex_mesh(options.smoothing_rounds, out);
    std::vector<int> block_of;
    for (size_t b = 0; b < out.blocks.size(); ++b) block_of.insert(block_of.end(), size_t(out.blocks[b].hexes), int(b));
    measure(block_of, out);
    out.off_tolerance_pairs = cx.off_tolerance_pairs;
    if (cx.off_tolerance_pairs > 0 && out.quality.inverted > 0) {
        HexMesh none;
        none.reason = std::to_string(out.quality.inverted) + " hexes came out inverted where " +
                      std::to_string(cx.off_tolerance_pairs) + " block pair(s) meet with their corners apart";
        return none;
    }
    if (options.order == 2) add_midpoints(mesh, cx, g, cad, out);
    out.done = true;
    return out;
}

int interfaces(const BlockComplex& cx) {
    return int(std::count_if(cx.faces.begin(), cx.faces.end(), [](const ComplexFace& f) { return !f.boundary; }));
}

// Hexes below this scaled Jacobian are poor: the flat corners' hexes (0 to 0.3), not the
// 45 degree corners of a triangle's template (about 0.7) nor a curved block's (0.4 to 0.6).
constexpr double kPoorScaledJacobian = 0.3;
// A refinement may lower the smallest scaled Jacobian by this much when it makes the poor hexes
// better (their shortfall below kPoorScaledJacobian, summed): the hex grid's smoothing moves the
// worst hex a little with every change of the complex.
constexpr double kMinJacobianSlack = 0.01;

double poor_shortfall(const HexMesh& m) {
    double sum = 0;
    for (double sj : m.scaled_jacobian) sum += std::max(0.0, kPoorScaledJacobian - sj);
    return sum;
}

// A refinement may make the hexes' volume miss the part's by this share more: a template joins
// short and long block edges into one class of equal hex counts, and a coarser grid on a curved
// face cuts more of it off (the sphere at 1 x went from 1.3 to 3 % under).
constexpr double kVolumeSlack = 0.005;

// A refined mesh is better when its volume misses `volume` (the part's) by at most the slack
// more, and it has fewer inverted hexes; with as many, a smallest scaled Jacobian higher by more
// than the slack, or not lower by more than it and less poor.
bool better(const HexMesh& refined, const HexMesh& plain, double volume) {
    if (!refined.done) return false;
    if (!plain.done) return true;
    const double miss = std::abs(refined.quality.volume - volume), was = std::abs(plain.quality.volume - volume);
    if (miss > was + kVolumeSlack * volume) return false;
    if (refined.quality.inverted != plain.quality.inverted) return refined.quality.inverted < plain.quality.inverted;
    const double rise = refined.quality.min_scaled_jacobian - plain.quality.min_scaled_jacobian;
    if (rise > kMinJacobianSlack) return true;
    return rise >= -kMinJacobianSlack && poor_shortfall(refined) < poor_shortfall(plain) - 1e-9;
}

// The hex mesh, or done = false with the reason; with refinement, of the better of the plain and
// the refined complex (docs/algorithms.md#flat-edge-refinement).
HexMesh mesh_blocks(const TetMesh& mesh, const BlockDecomposition& blocks, const HexMeshOptions& options,
                    const CadProjector& cad) {
    HexMesh out;
    BlockComplex cx = block_complex(mesh, blocks);
    if (!cx.failure.empty()) {
        out.reason = cx.failure;
        return out;
    }
    const double size = options.size > 0 ? options.size : kDefaultHexSizeInH * blocks.h, reach = kFlatReachInH * blocks.h;
    HexRefinement r;
    const FlatCount before = count_flat(cx, reach, options.flat_deg);
    r.blocks_before = r.blocks = int(cx.blocks.size());
    r.pairs_before = r.pairs = interfaces(cx);
    r.flat_edges_before = r.flat_edges = before.edges, r.flat_corners_before = r.flat_corners = before.corners;
    r.flat_corner_positions = before.where;
    out = mesh_complex(mesh, cx, size, options, cad);
    if (options.refine_flat) {
        BlockComplex refined_cx = cx;
        HexMesh best = out;  // the mesh of refined_cx: each refinement is kept when it beats it
        double volume = 0;   // the tet mesh's, for the refinements' volume test
        for (int t = 0; t < mesh.num_tets(); ++t) volume += tet_volume(mesh, t);
        auto keep = [&](const BlockComplex& tried) {
            HexMesh m = mesh_complex(mesh, tried, size, options, cad);
            if (!better(m, best, volume)) return false;
            best = std::move(m);
            return true;
        };
        const FlatRefinement f = refine_flat_edges(mesh, reach, kRefineCandidateDeg, kRefineEndDeg, refined_cx, keep);
        r.applied = true, r.refined = f.refined, r.skipped = f.skipped;
        r.plain_min_scaled_jacobian = out.done ? out.quality.min_scaled_jacobian : 0;
        r.kept = f.refined > 0;
        if (r.kept) {
            r.refined_min_scaled_jacobian = best.quality.min_scaled_jacobian;
            const FlatCount after = count_flat(refined_cx, reach, options.flat_deg);
            r.blocks = int(refined_cx.blocks.size()), r.pairs = interfaces(refined_cx);
            r.flat_edges = after.edges, r.flat_corners = after.corners, r.flat_corner_positions = after.where;
            out = std::move(best);
        }
    }
    out.refinement = r;
    return out;
}

}  // namespace

HexMesh build_hexmesh(const TetMesh& mesh, const BlockDecomposition& blocks, const HexMeshOptions& options,
                      const CadProjector& cad) {
    const auto t0 = std::chrono::steady_clock::now();
    HexMesh out;
    try {
        out = mesh_blocks(mesh, blocks, options, cad);
    } catch (const Error& e) {
        out = HexMesh{};
        out.reason = e.message();
    }
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
}

}  // namespace framefix
