// Validation of all blocks of a decomposition at once, reusing earlier results where a block is
// unchanged, and the blocks' score (docs/algorithms.md#block-validation).
#include <algorithm>
#include <numeric>

#include <omp.h>

#include "framefix/blocks/validation.h"

namespace framefix {
namespace {

int relabelled(int label, const std::vector<int>& new_of_old) { return label >= 0 ? new_of_old[label] : label; }

// Whether block b's boundary is the earlier block's, labels mapped to the new ids.
bool same_boundary(const std::vector<BoundaryTriangle>& now, const EarlierBlocks& e, int b) {
    const int o = e.old_of_new[b];
    if (o < 0 || e.validated.surface[o].size() != now.size()) return false;
    const auto& then = e.validated.surface[o];
    for (size_t i = 0; i < now.size(); ++i)
        if (now[i].verts != then[i].verts || now[i].label != relabelled(then[i].label, e.new_of_old)) return false;
    return true;
}

// The earlier block's validation, its labels mapped to the new ids.
void reuse_validation(const EarlierBlocks& e, int b, BlockFaces& faces, BlockInfo& info) {
    const int o = e.old_of_new[b];
    faces = e.validated.faces[o];
    for (int& l : faces.label) l = relabelled(l, e.new_of_old);
    for (int& l : faces.cleaned) l = relabelled(l, e.new_of_old);
    const BlockInfo& then = e.blocks.blocks[o];
    info.valid = then.valid, info.faces = then.faces, info.edges = then.edges, info.corners = then.corners;
    info.face_corners_off = then.face_corners_off;
    info.euler = then.euler, info.manifold = then.manifold, info.flat_edges = then.flat_edges;
    info.flat_corners = then.flat_corners, info.reason = then.reason, info.centroid = then.centroid;
}

// Mean of the vertices of `tets`.
Eigen::Vector3d vertex_centroid(const TetMesh& mesh, const std::vector<int>& tets) {
    thread_local std::vector<char> seen;  // per vertex, all 0 between calls
    seen.resize(size_t(mesh.num_vertices()), 0);
    std::vector<int> verts;
    for (int t : tets)
        for (int k = 0; k < 4; ++k)
            if (const int v = mesh.tets(t, k); !seen[size_t(v)]) seen[size_t(v)] = 1, verts.push_back(v);
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int v : verts) c += mesh.points.row(v).transpose(), seen[size_t(v)] = 0;
    return verts.empty() ? c : Eigen::Vector3d(c / double(verts.size()));
}

}  // namespace

BoundaryTriangle boundary_triangle(const TetMesh& mesh, const TetTopology& topo, const std::vector<int>& group, int f,
                                   int t, int other) {
    BoundaryTriangle tri;
    tri.verts = topo.faces.row(f).transpose();
    tri.label = other >= 0 ? other : -1 - group[f];
    const Eigen::Vector3d p0 = mesh.points.row(tri.verts[0]).transpose();
    tri.normal = (mesh.points.row(tri.verts[1]).transpose() - p0).cross(mesh.points.row(tri.verts[2]).transpose() - p0);
    Eigen::Vector3d inner = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k) inner += mesh.points.row(mesh.tets(t, k)).transpose() / 4;
    if (tri.normal.dot(p0 - inner) < 0) tri.normal = -tri.normal;
    return tri;
}

Validated collect_boundaries(const TetMesh& mesh, const TetTopology& topo, const std::vector<int>& group,
                             BlockDecomposition& out) {
    out.blocks.assign(out.count, BlockInfo{});
    Validated v;
    v.shared.assign(out.count, {});
    v.surface.assign(out.count, {});
    auto& surface = v.surface;
    for (int f = 0; f < int(topo.faces.rows()); ++f) {
        const int ta = topo.face_tets(f, 0), tb = topo.face_tets(f, 1);
        const int la = out.tet_block[ta], lb = tb >= 0 ? out.tet_block[tb] : -1;
        if (la == lb) continue;
        for (int side = 0; side < 2; ++side) {
            const int t = side == 0 ? ta : tb, b = side == 0 ? la : lb, other = side == 0 ? lb : la;
            if (b < 0) continue;
            surface[b].push_back(boundary_triangle(mesh, topo, group, f, t, other));
            if (other >= 0) v.shared[b][other] += 1;
        }
    }
    for (int t = 0; t < mesh.num_tets(); ++t) {
        BlockInfo& info = out.blocks[out.tet_block[t]];
        info.tets.push_back(t);
        info.volume += tet_volume(mesh, t);
    }
    return v;
}

void validate_collected(const TetMesh& mesh, double h, const BlockOptions& options, BlockDecomposition& out,
                        Validated& v, const EarlierBlocks* earlier) {
    const auto& surface = v.surface;
    v.faces.resize(out.count);
#pragma omp parallel for schedule(dynamic, 1) num_threads(options.threads > 0 ? options.threads : omp_get_max_threads())
    for (int b = 0; b < out.count; ++b) {
        BlockInfo& info = out.blocks[b];
        for (auto [o, n] : v.shared[b]) info.neighbours.push_back(o);
        if (earlier && same_boundary(surface[b], *earlier, b)) {
            reuse_validation(*earlier, b, v.faces[b], info);
            continue;
        }
        v.faces[b] = validate_block(mesh, surface[b], h, options, info);
        info.centroid = vertex_centroid(mesh, info.tets);
    }
    // Both sides of an interface agree: a contact one side cleaned away as a sliver is one on the
    // other side too. Before the lens test: what is left may be a lens (the sphere's slabs).
    const std::vector<std::vector<int>> one_sided = one_sided_contacts(v.faces, v.shared);
    for (int b = 0; b < out.count; ++b)
        if (!one_sided[b].empty()) v.faces[b] = validate_block(mesh, v.surface[b], h, options, out.blocks[b], one_sided[b]);
}

Validated validate_blocks(const TetMesh& mesh, const TetTopology& topo, const std::vector<int>& group, double h,
                          const BlockOptions& options, BlockDecomposition& out) {
    Validated v = collect_boundaries(mesh, topo, group, out);
    validate_collected(mesh, h, options, out, v);
    return v;
}

void validate_relabelled(const TetMesh& mesh, double h, const BlockOptions& options, const BlockDecomposition& out,
                         const Validated& v, BlockDecomposition& tried, Validated& w) {
    std::vector<int> same(size_t(out.count));
    std::iota(same.begin(), same.end(), 0);
    const EarlierBlocks earlier{out, v, same, same};
    validate_collected(mesh, h, options, tried, w, &earlier);
    count_conformity(w, h, options, tried);
}

void count_conformity(const Validated& v, double h, const BlockOptions& options, BlockDecomposition& out) {
    out.neighbour_pairs = check_conformity(v.faces, options.conform_tolerance * h);
    out.valid = out.flat_edges = out.flat_corners = out.conforming_pairs = 0;
    for (const BlockInfo& b : out.blocks)
        out.valid += b.valid, out.flat_edges += b.flat_edges, out.flat_corners += b.flat_corners;
    out.pairs = int(out.neighbour_pairs.size());
    for (const BlockPair& p : out.neighbour_pairs) out.conforming_pairs += p.conforming;
}

std::tuple<bool, int, int> score(const BlockDecomposition& b) {
    return {b.valid == b.count && b.conforming_pairs == b.pairs, 2 * b.valid - b.count, 2 * b.conforming_pairs - b.pairs};
}

}  // namespace framefix
