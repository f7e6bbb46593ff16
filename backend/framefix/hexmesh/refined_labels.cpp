// The tets of blocks the flat-edge refinement cut, given to the parts' hexes (hexmesh.h).
#include <algorithm>
#include <map>

#include "framefix/hexmesh/hexmesh.h"
#include "framefix/streamlines/point_grid.h"
#include "framefix/streamlines/tet_locator.h"

namespace framefix {
namespace {

Eigen::Vector3d hex_centre(const HexMesh& hm, const std::array<int, 8>& hex) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int v : hex) c += hm.points.row(v).transpose();
    return c / 8;
}

Eigen::Vector3d tet_centre(const TetMesh& mesh, int t) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k) c += mesh.points.row(mesh.tets(t, k)).transpose();
    return c / 4;
}

// The block each of the hex mesh's blocks was cut from: its own id below blocks_before, else
// the block most of its hex centres lie in.
std::vector<int> parent_blocks(const TetMesh& mesh, const TetTopology& topo, const Eigen::VectorXi& tet_block,
                               const HexMesh& hm) {
    const int before = hm.refinement.blocks_before, n = int(hm.blocks.size());
    std::vector<int> parent(size_t(n), -1);
    std::vector<std::map<int, int>> votes(hm.blocks.size());
    const TetLocator locator(mesh, topo);
    int last = -1;
    for (size_t h = 0; h < hm.hexes.size(); ++h) {
        const int b = hm.hex_block[h];
        if (b < before) continue;
        const TetLocation at = locator.locate(hex_centre(hm, hm.hexes[h]), last);
        if (at.tet < 0) continue;
        last = at.tet;
        votes[size_t(b)][tet_block[at.tet]] += 1;
    }
    for (int b = 0; b < n; ++b) {
        if (b < before) parent[size_t(b)] = b;
        else if (!votes[size_t(b)].empty())
            parent[size_t(b)] = std::max_element(votes[size_t(b)].begin(), votes[size_t(b)].end(),
                                                 [](const auto& x, const auto& y) { return x.second < y.second; })->first;
    }
    return parent;
}

}  // namespace

Eigen::VectorXi refined_tet_blocks(const TetMesh& mesh, const TetTopology& topo, const Eigen::VectorXi& tet_block,
                                   const HexMesh& hm) {
    Eigen::VectorXi out = tet_block;
    if (!hm.done || !hm.refinement.kept) return out;
    const std::vector<int> parent = parent_blocks(mesh, topo, tet_block, hm);
    std::map<int, std::vector<int>> parts;  // block cut -> its parts' ids
    for (int b = 0; b < int(parent.size()); ++b)
        if (parent[size_t(b)] >= 0) parts[parent[size_t(b)]].push_back(b);
    for (const auto& [block, ids] : parts) {
        if (ids.size() < 2) continue;
        std::vector<int> owner;  // per hex centre in the grid: its part
        std::vector<Eigen::Vector3d> centres;
        for (size_t h = 0; h < hm.hexes.size(); ++h)
            if (std::binary_search(ids.begin(), ids.end(), hm.hex_block[h]))
                centres.push_back(hex_centre(hm, hm.hexes[h])), owner.push_back(hm.hex_block[h]);
        Points p(Eigen::Index(centres.size()), 3);
        for (size_t i = 0; i < centres.size(); ++i) p.row(Eigen::Index(i)) = centres[i].transpose();
        const PointGrid grid(p, hm.size);
        // A tet's nearest hex centre lies within a hex diagonal unless the tet is in a corner the
        // hexes cut off; those keep the block's own id.
        const double reach = 2 * hm.size;
        for (int t = 0; t < mesh.num_tets(); ++t) {
            if (tet_block[t] != block) continue;
            const int i = grid.nearest(tet_centre(mesh, t), reach);
            if (i >= 0) out[t] = owner[size_t(i)];
        }
    }
    return out;
}

}  // namespace framefix
