// Block faces across ambiguous feature curves: the surface groups the block faces are made of, and
// which ambiguous edges (a chamfer's) the faces run across (docs/algorithms.md#block-faces-across-ambiguous-edges).
#include "framefix/blocks/ambiguous_edges.h"

#include <algorithm>
#include <map>
#include <set>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

#include "framefix/core/disjoint_set.h"
#include "framefix/mesh/keys.h"

namespace framefix {
namespace {

// How far the invalid blocks are from a hexahedron: faces, edges and corners off 6, 12 and 8, and
// their faces' corners off 4.
int hex_defect(const BlockDecomposition& b) {
    int d = 0;
    for (const BlockInfo& i : b.blocks)
        if (!i.valid)
            d += std::abs(i.faces - 6) + std::abs(i.edges - 12) + std::abs(i.corners - 8) + i.face_corners_off;
    return d;
}

bool better(const BlockDecomposition& a, const BlockDecomposition& b) {
    return std::tuple(score(a), -hex_defect(a)) > std::tuple(score(b), -hex_defect(b));
}

// Blocks that are invalid or in a non-conforming pair.
std::vector<char> in_trouble(const BlockDecomposition& out) {
    std::vector<char> trouble(out.count, 0);
    for (int b = 0; b < out.count; ++b) trouble[b] = !out.blocks[b].valid;
    for (const BlockPair& p : out.neighbour_pairs)
        if (!p.conforming) trouble[p.a] = trouble[p.b] = 1;
    return trouble;
}

// Per ambiguous B-rep edge, the blocks with a boundary triangle at one of its mesh vertices: the
// only blocks whose faces its join changes.
std::unordered_map<int, std::vector<int>> blocks_at_edges(const TetMesh& mesh, const FeatureSet& features,
                                                          const Validated& v) {
    std::unordered_map<int, std::vector<int>> tags_at;  // mesh vertex -> ambiguous edges through it
    for (int e = 0; e < int(mesh.feature_edges.rows()); ++e) {
        const int tag = mesh.edge_tags[e];
        if (tag < 1 || tag > int(features.edges.size()) || !ambiguous_edge(features.edges[size_t(tag - 1)])) continue;
        for (int k = 0; k < 2; ++k) tags_at[mesh.feature_edges(e, k)].push_back(tag);
    }
    std::unordered_map<int, std::set<int>> blocks;
    for (int b = 0; b < int(v.surface.size()); ++b)
        for (const BoundaryTriangle& t : v.surface[b])
            for (int k = 0; k < 3 && t.label < 0; ++k)
                if (auto it = tags_at.find(t.verts[k]); it != tags_at.end())
                    for (int tag : it->second) blocks[tag].insert(b);
    std::unordered_map<int, std::vector<int>> out;
    for (auto& [tag, set] : blocks) out[tag].assign(set.begin(), set.end());
    return out;
}

// `out` with B-rep edge `e` joined too, validated again where a block's boundary labels changed.
BlockDecomposition try_join(const TetMesh& mesh, const TetTopology& topo, const FeatureSet& features,
                            const std::vector<SnappedPath>& paths, double h, const BlockOptions& options,
                            const BlockDecomposition& out, const Validated& v, int e, Validated& w) {
    BlockDecomposition tried = out;
    tried.joined_edges.push_back(e);
    std::sort(tried.joined_edges.begin(), tried.joined_edges.end());
    w = collect_boundaries(mesh, topo, joined_groups(mesh, topo, features, paths, tried), tried);
    validate_relabelled(mesh, h, options, out, v, tried, w);
    return tried;
}

}  // namespace

std::vector<int> surface_groups(const TetMesh& mesh, const TetTopology& topo, const FeatureSet& features,
                                const std::vector<int>& joined, const std::vector<SnappedPath>& paths) {
    const std::uint64_t nv = mesh.num_vertices();
    auto ekey = [nv](int a, int b) { return edge_key(a, b, nv); };
    std::unordered_set<PairKey> border;
    for (int e = 0; e < int(mesh.feature_edges.rows()); ++e)
        if (features.valence_of(mesh.edge_tags[e]) > 0 &&
            !std::binary_search(joined.begin(), joined.end(), mesh.edge_tags[e]))
            border.insert(ekey(mesh.feature_edges(e, 0), mesh.feature_edges(e, 1)));
    for (const SnappedPath& p : paths)
        for (size_t i = 0; i + 1 < p.vertices.size(); ++i) border.insert(ekey(p.vertices[i], p.vertices[i + 1]));
    const int nb = int(mesh.boundary_faces.rows());
    DisjointSet groups(nb);
    std::unordered_map<PairKey, int> first_face;  // boundary edge -> the first boundary face seen on it
    for (int b = 0; b < nb; ++b)
        for (int k = 0; k < 3; ++k) {
            const PairKey key = ekey(mesh.boundary_faces(b, k), mesh.boundary_faces(b, (k + 1) % 3));
            auto [it, fresh] = first_face.try_emplace(key, b);
            if (!fresh && !border.count(key)) groups.unite(it->second, b);
        }
    std::unordered_map<TriangleKey, int, TriangleKeyHash> face_of;  // sorted triangle -> boundary face
    auto tkey = [](const auto& f) { return triangle_key(f(0), f(1), f(2)); };
    for (int b = 0; b < nb; ++b) face_of[tkey(mesh.boundary_faces.row(b))] = b;
    std::vector<int> group(topo.faces.rows(), -1);
    for (int f = 0; f < int(topo.faces.rows()); ++f) {
        if (topo.face_tets(f, 1) >= 0) continue;
        auto it = face_of.find(tkey(topo.faces.row(f)));
        group[f] = it == face_of.end() ? 0 : groups.find(it->second);
    }
    return group;
}

std::vector<int> joined_groups(const TetMesh& mesh, const TetTopology& topo, const FeatureSet& features,
                               const std::vector<SnappedPath>& paths, const BlockDecomposition& out) {
    std::vector<int> joined = out.ignored_imprints;
    joined.insert(joined.end(), out.joined_edges.begin(), out.joined_edges.end());
    std::sort(joined.begin(), joined.end());
    return surface_groups(mesh, topo, features, joined, paths);
}

namespace {

using JoinKey = std::tuple<std::tuple<bool, int, int>, int>;  // score, then minus the defect
JoinKey key_of(const BlockDecomposition& b) { return {score(b), -hex_defect(b)}; }

// Full rounds (every candidate tried, the best joined) while the tries have validated fewer tets
// than kFullRoundsWork times the part's; then each round tries the edges in the order of their
// last try's blocks, best first, and joins the first that is better than no join; the search
// stops at kJoinWork times. On a one-block part (HexMe's icosahedron, 30 edges) full rounds to
// the end cost 400 validations of the whole part (10 s at 1 x, minutes at 0.7 x), the old single
// pass in id order 30 (4 s). On chamfer_top the first full round picks the join the later
// rounds' order needs.
constexpr double kFullRoundsWork = 10;
constexpr double kJoinWork = 40;

void best_first_joins(const TetMesh& mesh, const TetTopology& topo, const FeatureSet& features,
                      const std::vector<SnappedPath>& paths, double h, const BlockOptions& options,
                      BlockDecomposition& out, Validated& v) {
    const std::unordered_map<int, std::vector<int>> touched = blocks_at_edges(mesh, features, v);
    std::map<int, JoinKey> last;  // edge -> the key of its last try
    double work = 0;              // tets validated by the tries
    const double budget = kFullRoundsWork * double(mesh.num_tets());
    while (!std::get<0>(score(out)) && work < kJoinWork * double(mesh.num_tets())) {
        const bool full = work < budget;
        const std::vector<char> trouble = in_trouble(out);
        std::vector<int> candidates;
        for (const EdgeFeature& e : features.edges) {
            auto it = touched.find(e.edge);
            if (it == touched.end() || std::binary_search(out.joined_edges.begin(), out.joined_edges.end(), e.edge))
                continue;
            // A join among blocks all valid and conforming can only make them worse.
            if (std::any_of(it->second.begin(), it->second.end(), [&](int b) { return trouble[b]; }))
                candidates.push_back(e.edge);
        }
        auto last_key = [&](int e) { auto it = last.find(e); return it == last.end() ? JoinKey{} : it->second; };
        std::stable_sort(candidates.begin(), candidates.end(), [&](int a, int b) { return last_key(a) > last_key(b); });
        BlockDecomposition best;
        Validated best_v;
        bool found = false;
        for (int e : candidates) {
            Validated w;
            BlockDecomposition tried = try_join(mesh, topo, features, paths, h, options, out, v, e, w);
            for (int b : touched.at(e)) work += double(out.blocks[size_t(b)].tets.size());
            last[e] = key_of(tried);
            if (!better(tried, found ? best : out)) continue;
            best = std::move(tried), best_v = std::move(w), found = true;
            if (!full) break;
        }
        if (!found) return;
        out = std::move(best), v = std::move(best_v);
    }
}

}  // namespace

void join_ambiguous_edges(const TetMesh& mesh, const TetTopology& topo, const FeatureSet& features,
                          const std::vector<SnappedPath>& paths, double h, const BlockOptions& options,
                          BlockDecomposition& out, Validated& v) {
    // Every try copies `out`; the sheets, which no try changes, wait aside.
    SheetSoup sheets = std::move(out.sheets);
    best_first_joins(mesh, topo, features, paths, h, options, out, v);
    out.sheets = std::move(sheets);
}

}  // namespace framefix
