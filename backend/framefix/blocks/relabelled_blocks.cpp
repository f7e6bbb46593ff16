// A decomposition whose tets changed block after it was made, validated again (blocks.h).
#include <algorithm>
#include <map>
#include <utility>

#include "framefix/blocks/ambiguous_edges.h"
#include "framefix/blocks/block_surfaces.h"
#include "framefix/blocks/partition.h"
#include "framefix/blocks/validation.h"
#include "framefix/core/error.h"

namespace framefix {
namespace {

// The staircase cleaning of the partition on the changed blocks (`changed`, per label), then
// each cleaned block back to the id most of its tets had.
Eigen::VectorXi cleaned(const TetMesh& mesh, const TetTopology& topo, const Eigen::VectorXi& wanted,
                        const std::vector<char>& changed, const BlockOptions& options) {
    Eigen::VectorXi lab = clean_staircase(mesh, topo, wanted, changed);
    if (merge_small_pieces(topo, lab, small_piece_tets(mesh.num_tets(), options)) > 0)
        lab = clean_staircase(mesh, topo, std::move(lab), std::vector<char>(size_t(lab.maxCoeff() + 1), 1));
    std::vector<std::map<int, int>> votes(size_t(lab.maxCoeff() + 1));
    for (Eigen::Index t = 0; t < lab.size(); ++t) votes[size_t(lab[t])][wanted[t]] += 1;
    std::vector<int> id(votes.size());
    for (size_t b = 0; b < votes.size(); ++b)
        id[b] = std::max_element(votes[b].begin(), votes[b].end(), [](const auto& x, const auto& y) { return x.second < y.second; })->first;
    for (Eigen::Index t = 0; t < lab.size(); ++t) lab[t] = id[size_t(lab[t])];
    return lab;
}

}  // namespace

BlockDecomposition relabelled_blocks(const TetMesh& mesh, const TetTopology& topo, const FeatureSet& features,
                                     const std::vector<SnappedPath>& paths, const BlockDecomposition& before,
                                     Eigen::VectorXi tet_block, const BlockOptions& options) {
    if (tet_block.size() != before.tet_block.size()) throw Error("blocks", "relabelled blocks need one label per tet");
    BlockDecomposition out = before;
    // The changed blocks and their neighbours: a neighbour's boundary changes where it meets two parts
    // (left out, the sphere's and the filleted notch's parts at 0.7 x had non-manifold neighbours).
    std::vector<char> changed(size_t(std::max(before.count, tet_block.size() ? tet_block.maxCoeff() + 1 : 0)), 0);
    std::vector<char> cut(size_t(before.count), 0);
    for (Eigen::Index t = 0; t < tet_block.size(); ++t)
        if (tet_block[t] != before.tet_block[t]) changed[size_t(tet_block[t])] = cut[size_t(before.tet_block[t])] = 1;
    for (int b = 0; b < before.count; ++b)
        if (cut[size_t(b)]) {
            changed[size_t(b)] = 1;
            for (int n : before.blocks[size_t(b)].neighbours) changed[size_t(n)] = 1;
        }
    out.tet_block = cleaned(mesh, topo, tet_block, changed, options);
    // Ids are kept (the hex mesh's blocks are numbered so); only a gap renumbers them.
    out.count = out.tet_block.size() ? out.tet_block.maxCoeff() + 1 : 0;
    std::vector<char> used(size_t(out.count), 0);
    for (Eigen::Index t = 0; t < out.tet_block.size(); ++t) used[size_t(out.tet_block[t])] = 1;
    if (std::find(used.begin(), used.end(), 0) != used.end()) out.count = compact_labels(out.tet_block);
    out.trouble_before_joins.clear();
    const std::vector<int> group = joined_groups(mesh, topo, features, paths, out);
    Validated v = validate_blocks(mesh, topo, group, out.h, options, out);
    count_conformity(v, out.h, options, out);
    out.surfaces = block_surfaces(mesh, v.surface, v.faces);
    out.boundary = std::move(v.surface);
    out.faces = std::move(v.faces);
    return out;
}

}  // namespace framefix
