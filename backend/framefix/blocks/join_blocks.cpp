// Under-faced blocks joined to a neighbour (docs/algorithms.md#under-faced-blocks).
#include "framefix/blocks/join_blocks.h"

#include <algorithm>
#include <initializer_list>
#include <optional>
#include <set>
#include <tuple>
#include <utility>

#include "framefix/blocks/carried_cuts.h"
#include "framefix/blocks/partition.h"

namespace framefix {
namespace {

// A wedge is shared between two of its this many largest contacts: the two sheets that cut it off.
constexpr size_t kSplitContacts = 3;

using Tried = std::optional<std::pair<BlockDecomposition, Validated>>;

// Invalid blocks of fewer than 6 faces, smallest first: wedges and slivers a sheet cut off a
// block (no hexahedron has fewer faces).
std::vector<int> under_faced_blocks(const BlockDecomposition& out) {
    std::vector<int> under;
    for (int b = 0; b < out.count; ++b)
        if (!out.blocks[b].valid && out.blocks[b].faces < 6 && !out.blocks[b].neighbours.empty()) under.push_back(b);
    std::sort(under.begin(), under.end(), [&](int a, int b) { return out.blocks[a].volume < out.blocks[b].volume; });
    return under;
}

// Whether blocks `from` and `into` together, before any staircase cleaning, have a manifold
// sphere boundary of fewer than 6 faces: the cleaning moves a few tets where a boundary is not a
// manifold and adds no face, so the join is not worth its cost (several times this check's).
bool hopeless_join(const TetMesh& mesh, const TetTopology& topo, const std::vector<int>& group, double h,
                   const BlockOptions& options, const BlockDecomposition& out, int from, int into) {
    auto inside = [&](int t) { return t >= 0 && (out.tet_block[t] == from || out.tet_block[t] == into); };
    std::vector<std::pair<int, int>> faces;  // (face, tet inside), in face order as collect_boundaries lists them
    for (int b : {from, into})
        for (int t : out.blocks[b].tets)
            for (int k = 0; k < 4; ++k)
                if (!inside(tet_across(topo, topo.tet_faces(t, k), t))) faces.push_back({topo.tet_faces(t, k), t});
    std::sort(faces.begin(), faces.end());
    std::vector<BoundaryTriangle> surface;
    for (auto [f, t] : faces) {
        const int across = tet_across(topo, f, t);
        surface.push_back(boundary_triangle(mesh, topo, group, f, t, across >= 0 ? out.tet_block[across] : -1));
    }
    BlockInfo joined;
    validate_block(mesh, surface, h, options, joined);
    return !joined.valid && joined.manifold && joined.euler == 2 && joined.faces < 6;
}

// Block ids of `out` and of `tried` (out with `from`'s tets given to the blocks `into`) mapped
// both ways; the blocks that took tets have no earlier counterpart.
EarlierBlocks map_earlier(const BlockDecomposition& out, const Validated& v, const BlockDecomposition& tried, int from,
                          const std::vector<int>& into) {
    EarlierBlocks earlier{out, v, std::vector<int>(tried.count, -1), std::vector<int>(out.count, -1)};
    for (int b = 0; b < out.count; ++b) {
        const int n = tried.tet_block[out.blocks[b].tets.front()];
        earlier.new_of_old[b] = n;
        if (b != from && std::find(into.begin(), into.end(), b) == into.end()) earlier.old_of_new[n] = b;
    }
    return earlier;
}

// The blocks of `from` and its neighbours, flagged: where moving `from`'s tets can change a staircase.
std::vector<char> near_blocks(const BlockDecomposition& out, int from) {
    std::vector<char> near(out.count, 0);
    near[from] = 1;
    for (int n : out.blocks[from].neighbours) near[n] = 1;
    return near;
}

// `out` relabelled as `labels` (block `from` moved into the blocks `into`), cleaned where `near`
// flags and validated again; none when a block that took its tets is no hexahedron.
Tried relabelled_blocks(
    const TetMesh& mesh, const TetTopology& topo, const std::vector<int>& group, double h, const BlockOptions& options,
    const BlockDecomposition& out, const Validated& v, Eigen::VectorXi labels, const std::vector<char>& near, int from,
    const std::vector<int>& into) {
    BlockDecomposition tried = out;
    tried.tet_block = clean_staircase(mesh, topo, std::move(labels), near);
    tried.count = compact_labels(tried.tet_block);
    Validated w = collect_boundaries(mesh, topo, group, tried);
    for (int b : into) {
        BlockInfo joined;
        validate_block(mesh, w.surface[tried.tet_block[out.blocks[b].tets.front()]], h, options, joined);
        if (!joined.valid && joined.faces < 6) return std::nullopt;  // dissolving contacts only removes faces
    }
    const EarlierBlocks earlier = map_earlier(out, v, tried, from, into);  // the others keep their results
    validate_collected(mesh, h, options, tried, w, &earlier);
    // Every block that took `from`'s tets must be a hexahedron: the cleaning may hand some to a
    // neighbour, and merging an invalid block into another invalid one would score better and
    // help nobody (a ring's pieces back into a ring).
    for (int t : out.blocks[from].tets)
        if (!tried.blocks[tried.tet_block[t]].valid) return std::nullopt;
    count_conformity(w, h, options, tried);
    return std::pair{std::move(tried), std::move(w)};
}

// `out` with block `from` joined to block `into`; none when the joined block is no hexahedron.
Tried joined_blocks(const TetMesh& mesh, const TetTopology& topo, const std::vector<int>& group, double h,
                    const BlockOptions& options, const BlockDecomposition& out, const Validated& v, int from,
                    int into) {
    if (hopeless_join(mesh, topo, group, h, options, out, from, into)) return std::nullopt;
    Eigen::VectorXi labels = out.tet_block;
    for (int t : out.blocks[from].tets) labels[t] = into;
    std::vector<char> near = near_blocks(out, from);
    for (int n : out.blocks[into].neighbours) near[n] = 1;
    return relabelled_blocks(mesh, topo, group, h, options, out, v, std::move(labels), near, from, {into});
}

// Blocks named by their first tets and sizes, so that a try that failed is not repeated while
// its blocks stay as they were.
using BlocksName = std::vector<int>;
BlocksName blocks_name(const BlockDecomposition& out, std::initializer_list<int> blocks) {
    BlocksName name;
    for (int b : blocks) name.push_back(out.blocks[b].tets.front()), name.push_back(int(out.blocks[b].tets.size()));
    return name;
}

// The neighbours block b shares the most boundary triangles with, most first, at most `count`.
std::vector<int> largest_contacts(const Validated& v, int b, size_t count) {
    std::vector<std::pair<int, int>> by_size;  // (-triangles, neighbour)
    for (auto [n, k] : v.shared[b]) by_size.push_back({-k, n});
    std::sort(by_size.begin(), by_size.end());
    std::vector<int> out;
    for (size_t i = 0; i < std::min(count, by_size.size()); ++i) out.push_back(by_size[i].second);
    return out;
}

// `tried` into `out` when it scores better; else its name goes to `failed`.
bool keep_better(Tried tried, const BlocksName& name, BlockDecomposition& out, Validated& v,
                 std::set<BlocksName>& failed) {
    if (!tried || !(score(tried->first) > score(out))) {
        failed.insert(name);
        return false;
    }
    out = std::move(tried->first), v = std::move(tried->second);
    return true;
}

// One join of an under-faced block to a neighbour that gives better blocks, into `out`. False if
// none does.
bool join_one(const TetMesh& mesh, const TetTopology& topo, const std::vector<int>& group, double h,
              const BlockOptions& options, BlockDecomposition& out, Validated& v, std::set<BlocksName>& failed) {
    for (int b : under_faced_blocks(out))
        for (int o : out.blocks[b].neighbours) {
            const BlocksName name = blocks_name(out, {b, o});
            if (!failed.count(name) &&
                keep_better(joined_blocks(mesh, topo, group, h, options, out, v, b, o), name, out, v, failed))
                return ++out.joined_blocks, true;
        }
    return false;
}

// One split of an under-faced block between two of its largest contacts that gives better
// blocks, into `out`. False if none does.
bool split_one(const TetMesh& mesh, const TetTopology& topo, const std::vector<int>& group, double h,
               const BlockOptions& options, BlockDecomposition& out, Validated& v, std::set<BlocksName>& failed) {
    for (int b : under_faced_blocks(out)) {
        const std::vector<int> c = largest_contacts(v, b, kSplitContacts);
        for (size_t i = 0; i < c.size(); ++i)
            for (size_t j = i + 1; j < c.size(); ++j) {
                // Two sheets that should be one have hexahedra on their far sides; sharing a
                // wedge with a block that is no hexahedron rarely makes one, and each try costs a
                // validation of the blocks.
                if (!out.blocks[c[i]].valid || !out.blocks[c[j]].valid) continue;
                const BlocksName name = blocks_name(out, {b, c[i], c[j]});
                if (failed.count(name)) continue;
                Tried tried = split_between(mesh, topo, group, h, options, out, v, b, c[i], c[j]);
                if (keep_better(std::move(tried), name, out, v, failed)) return ++out.split_blocks, true;
            }
    }
    return false;
}

}  // namespace

// Two sheets that should be one, crossing at an angle, cut a wedge off between them; the split
// leaves one sheet in their middle.
Tried split_between(const TetMesh& mesh, const TetTopology& topo, const std::vector<int>& group, double h,
                    const BlockOptions& options, const BlockDecomposition& out, const Validated& v, int from, int a,
                    int b) {
    const BlockFaces& f = v.faces[from];
    std::vector<int> tri_side(v.surface[from].size(), -1);
    for (size_t i = 0; i < tri_side.size(); ++i) {
        const int across = f.label[size_t(f.patch[i])];
        tri_side[i] = across == a ? 0 : across == b ? 1 : -1;
    }
    const CarriedCut cut = cut_alone(mesh, topo, out, v, from, tri_side);
    Eigen::VectorXi labels = out.tet_block;
    for (int t : out.blocks[from].tets) labels[t] = cut.side[size_t(t)] == 0 ? a : b;
    std::vector<char> near = near_blocks(out, from);
    for (int x : {a, b})
        for (int n : out.blocks[x].neighbours) near[n] = 1;
    return relabelled_blocks(mesh, topo, group, h, options, out, v, std::move(labels), near, from, {a, b});
}

void join_under_faced(const TetMesh& mesh, const TetTopology& topo, const std::vector<int>& group, double h,
                      const BlockOptions& options, BlockDecomposition& out, Validated& v) {
    std::set<BlocksName> failed;
    for (int round = 0; round < options.join_rounds; ++round)
        if (!join_one(mesh, topo, group, h, options, out, v, failed) &&
            !(options.split_wedges && split_one(mesh, topo, group, h, options, out, v, failed)))
            break;
}

}  // namespace framefix
