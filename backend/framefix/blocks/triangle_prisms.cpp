// Triangular prism blocks made hexahedra by a flat corner on a boundary face
// (docs/algorithms.md#triangular-prisms).
#include "framefix/blocks/triangle_prisms.h"

#include <algorithm>
#include <optional>

#include "framefix/blocks/prism_cuts.h"
#include "framefix/core/segment_distance.h"

namespace framefix {
namespace {

Eigen::Vector3d centre(const TetMesh& mesh, const BoundaryTriangle& t) {
    return (mesh.points.row(t.verts[0]) + mesh.points.row(t.verts[1]) + mesh.points.row(t.verts[2])).transpose() / 3;
}

// A label no boundary triangle of the decomposition carries: a surface group of its own.
int fresh_label(const Validated& v) {
    int lowest = -1;
    for (const auto& surface : v.surface)
        for (const BoundaryTriangle& t : surface) lowest = std::min(lowest, t.label);
    return lowest - 1;
}

// Relabels the triangles of lateral face i of block b's prism that lie nearer its edge with the
// next lateral face than its edge with the previous one: the face splits along its middle.
void split_lateral(const TetMesh& mesh, const Prism& prism, const BlockFaces& f, int i, int label,
                   std::vector<BoundaryTriangle>& surface) {
    const int n = prism.n;
    auto edge_at = [&](int e) { return std::pair{f.corner_position[prism.edge[e][0]], f.corner_position[prism.edge[e][1]]}; };
    const auto [a0, a1] = edge_at(i);            // shared with lateral i - 1
    const auto [b0, b1] = edge_at((i + 1) % n);  // shared with lateral i + 1
    for (size_t k = 0; k < surface.size(); ++k) {
        if (f.patch[k] != prism.laterals[i]) continue;
        const Eigen::Vector3d c = centre(mesh, surface[k]);
        if (point_segment_distance(c, b0, b1) < point_segment_distance(c, a0, a1)) surface[k].label = label;
    }
}

int non_conforming(const BlockDecomposition& b) { return b.pairs - b.conforming_pairs; }

// Block b with lateral face i split, validated again (the other blocks keep their results).
BlockDecomposition with_split(const TetMesh& mesh, const TetTopology& topo, const std::vector<int>& group, double h,
                              const BlockOptions& options, const BlockDecomposition& out, const Validated& v, int b,
                              const Prism& prism, int i, Validated& w) {
    BlockDecomposition tried = out;
    w = collect_boundaries(mesh, topo, group, tried);
    // The earlier splits first: collect_boundaries labels by surface group only.
    for (int o = 0; o < out.count; ++o) w.surface[o] = v.surface[o];
    split_lateral(mesh, prism, v.faces[b], i, fresh_label(v), w.surface[b]);
    validate_relabelled(mesh, h, options, out, v, tried, w);
    return tried;
}

}  // namespace

void fold_triangle_prisms(const TetMesh& mesh, const TetTopology& topo, const std::vector<int>& group, double h,
                          const BlockOptions& options, BlockDecomposition& out, Validated& v) {
    constexpr int kTriangle = 3;
    for (int b = 0; b < out.count; ++b) {
        if (out.blocks[b].valid) continue;
        const std::optional<Prism> prism = prism_of(v.faces[b], out.blocks[b], kTriangle);
        if (!prism || prism->n != kTriangle) continue;
        std::optional<std::pair<BlockDecomposition, Validated>> best;
        for (int i = 0; i < kTriangle; ++i) {
            if (v.faces[b].label[prism->laterals[i]] >= 0) continue;  // an interface: its neighbour would see two faces
            Validated w;
            BlockDecomposition tried = with_split(mesh, topo, group, h, options, out, v, b, *prism, i, w);
            const BlockDecomposition& than = best ? best->first : out;
            if (tried.valid > out.valid && non_conforming(tried) <= non_conforming(out) && score(tried) > score(than))
                best = std::pair{std::move(tried), std::move(w)};
        }
        if (!best) continue;
        out = std::move(best->first), v = std::move(best->second);
        ++out.triangle_folds;
    }
}

}  // namespace framefix
