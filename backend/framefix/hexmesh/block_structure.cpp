#include "framefix/hexmesh/block_structure.h"

#include <algorithm>
#include <iterator>
#include <map>
#include <queue>
#include <unordered_map>

#include <Eigen/Geometry>

#include "framefix/core/disjoint_set.h"
#include "framefix/mesh/keys.h"

namespace framefix {

namespace {

// The first block or pair that cannot be meshed. A pair that shares one face with 4 corners on
// each side is meshed even when its corners lie further apart than the blocks' tolerance: the
// complex checks that both sides name the same corners (counted in `off_tolerance`).
std::string first_failure(const BlockDecomposition& d, int& off_tolerance) {
    for (int b = 0; b < d.count; ++b)
        if (!d.blocks[b].valid) return "block " + std::to_string(b) + " is not a hexahedron (" + d.blocks[b].reason + ")";
    for (const BlockPair& p : d.neighbour_pairs) {
        off_tolerance += !p.conforming && p.one_face;
        if (!p.conforming && !p.one_face)
            return "blocks " + std::to_string(p.a) + " and " + std::to_string(p.b) + " do not share one whole face (" + p.reason + ")";
    }
    if (int(d.faces.size()) != d.count || int(d.boundary.size()) != d.count) return "the decomposition carries no block faces";
    return "";
}

std::vector<int> corners_of_patch(const BlockFaces& f, int patch) {
    std::vector<int> out;
    for (int c = 0; c < int(f.corner_patches.size()); ++c)
        if (std::binary_search(f.corner_patches[c].begin(), f.corner_patches[c].end(), patch)) out.push_back(c);
    return out;
}

// Union of corner nodes that never puts two corners of one block into one set: where two
// corners of a block lie one mesh edge apart (a rounded box's cushions at its radial curves), a
// neighbour's cluster can touch both, and the block would meet itself at a corner.
class CornerSets {
public:
    CornerSets(const std::vector<int>& block_of) : sets_(int(block_of.size())), blocks_(block_of.size()) {
        for (size_t i = 0; i < block_of.size(); ++i) blocks_[i] = {block_of[i]};
    }
    int find(int a) { return sets_.find(a); }
    void unite(int a, int b) {
        a = sets_.find(a), b = sets_.find(b);
        if (a == b) return;
        std::vector<int> both;
        std::set_union(blocks_[size_t(a)].begin(), blocks_[size_t(a)].end(), blocks_[size_t(b)].begin(),
                       blocks_[size_t(b)].end(), std::back_inserter(both));
        if (both.size() < blocks_[size_t(a)].size() + blocks_[size_t(b)].size()) return;  // a block twice
        sets_.unite(a, b);
        blocks_[size_t(sets_.find(a))] = std::move(both);
    }

private:
    DisjointSet sets_;
    std::vector<std::vector<int>> blocks_;  // per root: the blocks of its corners, ascending
};

// Global corner of every (block, corner): corners sharing a mesh vertex, and the corners of a
// shared face matched nearest to nearest, are one, but never two corners of one block. Returns
// per block its corners' global ids.
std::vector<std::vector<int>> merge_corners(const TetMesh& mesh, const BlockDecomposition& d, BlockComplex& cx) {
    std::vector<int> offset(d.count + 1, 0);
    for (int b = 0; b < d.count; ++b) offset[b + 1] = offset[b] + int(d.faces[b].corner_vertices.size());
    std::vector<int> block_of(size_t(offset.back()));
    for (int b = 0; b < d.count; ++b) std::fill(block_of.begin() + offset[b], block_of.begin() + offset[b + 1], b);
    CornerSets sets(block_of);
    std::unordered_map<int, int> node_of_vertex;
    for (int b = 0; b < d.count; ++b)
        for (int c = 0; c < int(d.faces[b].corner_vertices.size()); ++c)
            for (int v : d.faces[b].corner_vertices[c]) {
                auto [it, fresh] = node_of_vertex.try_emplace(v, offset[b] + c);
                if (!fresh) sets.unite(it->second, offset[b] + c);
            }
    for (const BlockPair& p : d.neighbour_pairs) {
        const BlockFaces &fa = d.faces[p.a], &fb = d.faces[p.b];
        const auto pa = std::find(fa.label.begin(), fa.label.end(), p.b) - fa.label.begin();
        const auto pb = std::find(fb.label.begin(), fb.label.end(), p.a) - fb.label.begin();
        const std::vector<int> ca = corners_of_patch(fa, int(pa)), cb = corners_of_patch(fb, int(pb));
        for (int x : ca) {
            int best = -1;
            for (int y : cb)
                if (best < 0 || (fa.corner_position[x] - fb.corner_position[y]).norm() <
                                    (fa.corner_position[x] - fb.corner_position[best]).norm())
                    best = y;
            if (best >= 0) sets.unite(offset[p.a] + x, offset[p.b] + best);
        }
    }
    std::map<int, int> id_of_root;
    std::vector<std::vector<int>> global(d.count);
    std::vector<int> members;
    for (int b = 0; b < d.count; ++b)
        for (int c = 0; c < int(d.faces[b].corner_vertices.size()); ++c) {
            const int root = sets.find(offset[b] + c);
            auto [it, fresh] = id_of_root.try_emplace(root, int(cx.corners.size()));
            if (fresh) cx.corners.emplace_back(), members.push_back(0);
            ComplexCorner& corner = cx.corners[it->second];
            corner.position += d.faces[b].corner_position[c];
            members[it->second] += 1;
            corner.vertices.insert(corner.vertices.end(), d.faces[b].corner_vertices[c].begin(), d.faces[b].corner_vertices[c].end());
            global[b].push_back(it->second);
        }
    std::vector<char> brep_vertex(mesh.num_vertices(), 0);
    for (int i = 0; i < int(mesh.corner_vertices.size()); ++i) brep_vertex[mesh.corner_vertices[i]] = 1;
    for (size_t c = 0; c < cx.corners.size(); ++c) {
        ComplexCorner& corner = cx.corners[c];
        corner.position /= double(members[c]);
        std::sort(corner.vertices.begin(), corner.vertices.end());
        corner.vertices.erase(std::unique(corner.vertices.begin(), corner.vertices.end()), corner.vertices.end());
        for (int v : corner.vertices)
            if (brep_vertex[v]) corner.position = mesh.points.row(v).transpose();  // a CAD vertex stays exact
    }
    return global;
}

// Area-weighted centroid of each patch of a block's boundary triangles.
std::vector<Eigen::Vector3d> patch_centroids(const TetMesh& mesh, const std::vector<BoundaryTriangle>& S, const BlockFaces& f) {
    std::vector<Eigen::Vector3d> sum(f.label.size(), Eigen::Vector3d::Zero());
    std::vector<double> area(f.label.size(), 0);
    for (size_t i = 0; i < S.size(); ++i) {
        Eigen::Vector3d c = Eigen::Vector3d::Zero();
        for (int k = 0; k < 3; ++k) c += mesh.points.row(S[i].verts[k]).transpose() / 3;
        const double a = S[i].normal.norm();
        sum[f.patch[i]] += a * c, area[f.patch[i]] += a;
    }
    for (size_t p = 0; p < sum.size(); ++p) if (area[p] > 0) sum[p] /= area[p];
    return sum;
}

// The block's corners as a cube: corner (0,0,0) is its lowest global corner, the three faces
// there start the three axes, each axis ends at the face sharing no corner with its start.
// Returns the local corner -> block corner map and the axis faces (patches), or false.
bool cube_frame(const TetMesh& mesh, const std::vector<BoundaryTriangle>& S, const BlockFaces& f,
                const std::vector<int>& global, std::array<int, 8>& corner, std::array<std::array<int, 2>, 3>& axis) {
    if (f.corner_patches.size() != 8 || f.label.size() != 6) return false;
    const int c0 = int(std::min_element(global.begin(), global.end()) - global.begin());
    for (int a = 0; a < 3; ++a) {
        const int start = f.corner_patches[c0][a];
        int opposite = -1;
        for (int p = 0; p < 6; ++p) {
            bool shares = p == start;
            for (const auto& ps : f.corner_patches)
                shares |= std::binary_search(ps.begin(), ps.end(), p) && std::binary_search(ps.begin(), ps.end(), start);
            if (!shares) {
                if (opposite >= 0) return false;
                opposite = p;
            }
        }
        if (opposite < 0) return false;
        axis[a] = {start, opposite};
    }
    auto fill = [&] {
        for (int i = 0; i < 8; ++i) {
            std::vector<int> want{axis[0][i & 1], axis[1][(i >> 1) & 1], axis[2][(i >> 2) & 1]};
            std::sort(want.begin(), want.end());
            corner[i] = -1;
            for (int c = 0; c < 8; ++c)
                if (f.corner_patches[c] == want) corner[i] = c;
            if (corner[i] < 0) return false;
        }
        return true;
    };
    if (!fill()) return false;
    // Handedness from the faces, each axis running from its start face's centroid to its end
    // face's: the corners alone misread a thin cushion (the sphere's outer blocks, 0.6 h thick at
    // their corners and 2.7 h in the middle: one came out mirrored, all 80 hexes inverted).
    const std::vector<Eigen::Vector3d> c = patch_centroids(mesh, S, f);
    auto along = [&](int a) -> Eigen::Vector3d { return c[axis[a][1]] - c[axis[a][0]]; };
    if (along(0).dot(along(1).cross(along(2))) < 0) {
        std::swap(axis[1], axis[2]);
        return fill();
    }
    return true;
}

// Mesh vertices along the chain of mesh edges between patches p and q of block `f`, from corner
// ca's cluster to corner cb's (shortest path over those edges).
std::vector<int> edge_chain(const TetMesh& mesh, const std::vector<BoundaryTriangle>& S, const BlockFaces& f, int p, int q,
                            int ca, int cb) {
    const std::uint64_t nv = mesh.num_vertices();
    std::unordered_map<PairKey, std::pair<bool, bool>> sides;  // mesh edge -> (in p, in q)
    for (size_t t = 0; t < S.size(); ++t) {
        if (f.patch[t] != p && f.patch[t] != q) continue;
        for (int k = 0; k < 3; ++k) {
            auto& s = sides[edge_key(S[t].verts[k], S[t].verts[(k + 1) % 3], nv)];
            (f.patch[t] == p ? s.first : s.second) = true;
        }
    }
    std::unordered_map<int, std::vector<int>> nb;
    for (const auto& [key, s] : sides)
        if (s.first && s.second) {
            const auto [a, b] = key_ids(key, nv);
            nb[a].push_back(b), nb[b].push_back(a);
        }
    if (nb.empty()) return {};
    auto nearest = [&](const Eigen::Vector3d& x) {  // the lowest id on ties: deterministic
        int best = -1;
        double closest = 0;
        for (const auto& [v, w] : nb) {
            const double d = (mesh.points.row(v).transpose() - x).squaredNorm();
            if (best < 0 || d < closest || (d == closest && v < best)) best = v, closest = d;
        }
        return best;
    };
    const int source = nearest(f.corner_position[ca]), target = nearest(f.corner_position[cb]);
    std::unordered_map<int, double> dist{{source, 0}};
    std::unordered_map<int, int> from;
    using Item = std::pair<double, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
    open.push({0, source});
    while (!open.empty()) {
        const auto [d, v] = open.top();
        open.pop();
        if (d > dist[v] || v == target) continue;
        for (int w : nb[v]) {
            const double dw = d + (mesh.points.row(v) - mesh.points.row(w)).norm();
            auto it = dist.find(w);
            if (it == dist.end() || dw < it->second) dist[w] = dw, from[w] = v, open.push({dw, w});
        }
    }
    if (!dist.count(target)) return {};
    std::vector<int> chain{target};
    while (chain.back() != source) chain.push_back(from[chain.back()]);
    std::reverse(chain.begin(), chain.end());
    return chain;
}

Points edge_polyline(const TetMesh& mesh, const BlockComplex& cx, int a, int b, const std::vector<int>& chain) {
    std::vector<Eigen::Vector3d> pts{cx.corners[a].position};
    auto in = [&](int c, int v) { return std::binary_search(cx.corners[c].vertices.begin(), cx.corners[c].vertices.end(), v); };
    for (int v : chain)
        if (!in(a, v) && !in(b, v)) pts.push_back(mesh.points.row(v).transpose());
    pts.push_back(cx.corners[b].position);
    Points out(Eigen::Index(pts.size()), 3);
    for (size_t i = 0; i < pts.size(); ++i) out.row(Eigen::Index(i)) = pts[i].transpose();
    return out;
}

// What block_complex needs of one block while it adds the block's edges and faces.
struct BlockInput {
    int id;
    const BlockFaces& faces;
    const std::vector<BoundaryTriangle>& boundary;
    std::array<int, 8> corner;                // local corner -> the block's own corner index
    std::array<std::array<int, 2>, 3> axis;   // per axis: its start and end faces (patches)
};

// The block's 12 edges, each new one with its chain; false (and cx.failure) when one has none.
bool add_edges(const TetMesh& mesh, const BlockInput& in, std::map<std::pair<int, int>, int>& edge_of,
               ComplexBlock& blk, BlockComplex& cx) {
    for (int e = 0; e < 12; ++e) {
        const int dir = e / 4, r = e % 4;  // r: the other two indices, lowest axis first
        const int lo = std::min((dir + 1) % 3, (dir + 2) % 3), hi = std::max((dir + 1) % 3, (dir + 2) % 3);
        const auto [l0, l1] = edge_local_corners(e);
        const auto key = std::minmax(blk.corners[l0], blk.corners[l1]);
        auto [it, fresh] = edge_of.try_emplace({key.first, key.second}, int(cx.edges.size()));
        blk.edges[e] = it->second;
        if (!fresh) continue;
        ComplexEdge edge;
        edge.a = key.first, edge.b = key.second;
        const bool forward = blk.corners[l0] == edge.a;
        edge.chain = edge_chain(mesh, in.boundary, in.faces, in.axis[lo][r & 1], in.axis[hi][r >> 1],
                                in.corner[forward ? l0 : l1], in.corner[forward ? l1 : l0]);
        if (edge.chain.empty()) {
            cx.failure = "block " + std::to_string(in.id) + " has an edge with no mesh edges along it";
            return false;
        }
        edge.polyline = edge_polyline(mesh, cx, edge.a, edge.b, edge.chain);
        cx.edges.push_back(std::move(edge));
    }
    return true;
}

// The tet triangles of one patch, turned outward from the block.
std::vector<Eigen::Vector3i> patch_triangles(const TetMesh& mesh, const BlockInput& in, int patch) {
    std::vector<Eigen::Vector3i> out;
    for (size_t t = 0; t < in.boundary.size(); ++t) {
        if (in.faces.patch[t] != patch) continue;
        Eigen::Vector3i v = in.boundary[t].verts;
        const Eigen::Vector3d p0 = mesh.points.row(v[0]).transpose();
        const Eigen::Vector3d n = (mesh.points.row(v[1]).transpose() - p0).cross(mesh.points.row(v[2]).transpose() - p0);
        if (n.dot(in.boundary[t].normal) < 0) std::swap(v[1], v[2]);
        out.push_back(v);
    }
    return out;
}

// The block's 6 faces; an interface seen before must have the same corners (else cx.failure).
bool add_faces(const TetMesh& mesh, const BlockInput& in, std::map<std::pair<int, int>, int>& face_of_pair,
               ComplexBlock& blk, BlockComplex& cx) {
    for (int lf = 0; lf < 6; ++lf) {
        const int patch = in.axis[lf / 2][lf % 2], across = in.faces.label[patch];
        std::array<int, 4> corners{};
        const std::array<int, 4> local = face_local_corners(lf);
        for (int n = 0; n < 4; ++n) corners[n] = blk.corners[local[n]];
        int id = int(cx.faces.size());
        if (across >= 0) id = face_of_pair.try_emplace(std::minmax(in.id, across), id).first->second;
        blk.faces[lf] = id;
        if (id < int(cx.faces.size())) {  // the other block's side of this interface
            std::array<int, 4> mine = corners, theirs = cx.faces[id].corners;
            std::sort(mine.begin(), mine.end()), std::sort(theirs.begin(), theirs.end());
            if (mine == theirs) continue;
            cx.failure = "blocks " + std::to_string(in.id) + " and " + std::to_string(across) +
                         " see their shared face with different corners";
            return false;
        }
        cx.faces.push_back({corners, patch_triangles(mesh, in, patch), across < 0});
    }
    return true;
}

}  // namespace

std::array<int, 4> face_local_corners(int lf) {
    const int axis = lf / 2, side = lf % 2;
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    std::array<int, 4> out{};
    const int uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int n = 0; n < 4; ++n) {
        int ijk[3];
        ijk[axis] = side, ijk[u] = uv[n][0], ijk[v] = uv[n][1];
        out[n] = local_corner(ijk[0], ijk[1], ijk[2]);
    }
    return out;
}

std::array<int, 2> edge_local_corners(int e) {
    const int dir = e / 4, r = e % 4;  // r: the other two indices, lowest axis first
    const int lo = std::min((dir + 1) % 3, (dir + 2) % 3), hi = std::max((dir + 1) % 3, (dir + 2) % 3);
    int ijk0[3], ijk1[3];
    ijk0[dir] = 0, ijk1[dir] = 1;
    ijk0[lo] = ijk1[lo] = r & 1, ijk0[hi] = ijk1[hi] = r >> 1;
    return {local_corner(ijk0[0], ijk0[1], ijk0[2]), local_corner(ijk1[0], ijk1[1], ijk1[2])};
}

BlockComplex block_complex(const TetMesh& mesh, const BlockDecomposition& d) {
    BlockComplex cx;
    cx.failure = first_failure(d, cx.off_tolerance_pairs);
    if (!cx.failure.empty()) return cx;
    const std::vector<std::vector<int>> global = merge_corners(mesh, d, cx);
    std::map<std::pair<int, int>, int> edge_of, face_of_pair;
    for (int b = 0; b < d.count; ++b) {
        BlockInput in{b, d.faces[b], d.boundary[b], {}, {}};
        if (!cube_frame(mesh, in.boundary, in.faces, global[b], in.corner, in.axis)) {
            cx.failure = "block " + std::to_string(b) + "'s faces and corners do not form a cube";
            return cx;
        }
        ComplexBlock blk;
        blk.id = b;
        for (int i = 0; i < 8; ++i) blk.corners[i] = global[b][in.corner[i]];
        std::array<int, 8> sorted = blk.corners;
        std::sort(sorted.begin(), sorted.end());
        if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
            cx.failure = "block " + std::to_string(b) + " meets itself at a corner";
            return cx;
        }
        if (!add_edges(mesh, in, edge_of, blk, cx) || !add_faces(mesh, in, face_of_pair, blk, cx)) return cx;
        cx.blocks.push_back(blk);
    }
    return cx;
}

int edge_at(int l, int axis) {
    const int bits[3] = {l & 1, (l >> 1) & 1, (l >> 2) & 1};
    const int lo = std::min((axis + 1) % 3, (axis + 2) % 3), hi = std::max((axis + 1) % 3, (axis + 2) % 3);
    return 4 * axis + bits[lo] + 2 * bits[hi];
}

}  // namespace framefix
