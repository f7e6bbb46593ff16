#include <algorithm>
#include <chrono>
#include <map>
#include <optional>
#include <set>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

#include <omp.h>

#include "framefix/blocks/block_surfaces.h"
#include "framefix/blocks/blocks.h"
#include "framefix/blocks/curtain_corners.h"
#include "framefix/blocks/partition.h"
#include "framefix/blocks/ring_cuts.h"
#include "framefix/blocks/sheets.h"
#include "framefix/blocks/validation.h"
#include "framefix/core/disjoint_set.h"
#include "framefix/core/error.h"
#include "framefix/mesh/keys.h"

namespace framefix {

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

void check_inputs(const TetMesh& mesh, const TetTopology& topo, const FrameField& field, const SingularityGraph& graph) {
    const std::string nv = std::to_string(mesh.num_vertices());
    if (field.axes.rows() != mesh.num_vertices() || field.coefficients.rows() != mesh.num_vertices())
        throw Error("blocks", "frame field has " + std::to_string(field.axes.rows()) + " rows for " + nv +
                                  " vertices; solve the field on this mesh");
    if (topo.tet_faces.rows() != mesh.num_tets())
        throw Error("blocks", "topology has " + std::to_string(topo.tet_faces.rows()) + " tets, mesh " +
                                  std::to_string(mesh.num_tets()) + "; rebuild the topology");
    if (!graph.face_valence.empty() && int(graph.face_valence.size()) != int(topo.faces.rows()))
        throw Error("blocks", "singularity graph has " + std::to_string(graph.face_valence.size()) +
                                  " faces, topology " + std::to_string(topo.faces.rows()) + "; re-extract singularities");
}

// CAD surface group of each topology face (-1 inside): connected boundary triangles, split at
// feature curves and snapped paths (a snapped path is a block edge: the hex layers meet the
// surface there at 45 degrees), joined across everything else: a cylinder's seam, and the
// imprinted curves the field ignores (`ignored`). So one block face is not split there.
std::vector<int> surface_groups(const TetMesh& mesh, const TetTopology& topo, const FeatureSet& features,
                                const std::vector<int>& ignored, const std::vector<SnappedPath>& paths) {
    const std::uint64_t nv = mesh.num_vertices();
    auto ekey = [nv](int a, int b) { return edge_key(a, b, nv); };
    std::unordered_set<PairKey> border;
    for (int e = 0; e < int(mesh.feature_edges.rows()); ++e)
        if (features.valence_of(mesh.edge_tags[e]) > 0 &&
            !std::binary_search(ignored.begin(), ignored.end(), mesh.edge_tags[e]))
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

struct Validated {
    std::vector<std::vector<BoundaryTriangle>> surface;  // per block: its boundary triangles
    std::vector<BlockFaces> faces;               // per block, for the conformity check
    std::vector<std::map<int, int>> shared;      // per block: neighbour -> shared triangles
};

// An earlier validation of the same mesh whose blocks' results can be reused: `old_of_new` maps
// each block to its earlier id (-1: none), `new_of_old` the other way.
struct EarlierBlocks {
    const BlockDecomposition& blocks;
    const Validated& validated;
    std::vector<int> old_of_new, new_of_old;
};

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
    info.euler = then.euler, info.manifold = then.manifold, info.flat_edges = then.flat_edges;
    info.flat_corners = then.flat_corners, info.reason = then.reason, info.centroid = then.centroid;
}

// Each block's boundary triangles (labelled by neighbour block or surface group), triangles
// shared with each neighbour, tets and volume; the rest of out.blocks is reset.
// Face f of tet t on its block's boundary, labelled with the block across (`other`) or, on the
// part's boundary (-1), its surface group; the normal points out of tet t.
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

// Each collected block validated as a hexahedron; fills out.blocks. Blocks whose boundary is
// unchanged since `earlier` keep its results.
void validate_collected(const TetMesh& mesh, double h, const BlockOptions& options, BlockDecomposition& out,
                        Validated& v, const EarlierBlocks* earlier = nullptr) {
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
        std::set<int> verts;
        for (int t : info.tets) for (int k = 0; k < 4; ++k) verts.insert(mesh.tets(t, k));
        for (int v : verts) info.centroid += mesh.points.row(v).transpose() / double(verts.size());
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

// Each block with at most 3 faces joins the neighbour it shares the most boundary triangles with
// (a non-lens one first). True if any block changed.
bool merge_lenses(const std::vector<std::map<int, int>>& shared, BlockDecomposition& out) {
    auto lens = [&](int b) { return out.blocks[b].faces <= 3 && !out.blocks[b].neighbours.empty(); };
    std::vector<int> into(out.count, -1);
    for (int b = 0; b < out.count; ++b) {
        if (!lens(b)) continue;
        int best = -1;
        for (int o : out.blocks[b].neighbours)
            if (best < 0 || (lens(best) && !lens(o)) ||
                (lens(best) == lens(o) && shared[b].at(o) > shared[b].at(best)))
                best = o;
        into[b] = best;
    }
    bool any = false;
    for (int b = 0; b < out.count; ++b) {
        if (into[b] < 0 || (lens(into[b]) && into[into[b]] == b && b < into[b])) continue;  // no swaps
        any = true;
    }
    if (!any) return false;
    for (int t = 0; t < int(out.tet_block.size()); ++t) {
        const int b = out.tet_block[t];
        if (into[b] >= 0 && !(into[into[b]] == b && b < into[b])) out.tet_block[t] = into[b];
    }
    return true;
}

// A concave curve's direction jumps this close to a curtain corner's foot (in h) are the corner's
// own turn: the corner line emits it (curtain_corners.h).
constexpr double kMuteReach = 3;

// Sources of the corner lines below the convex paths' feet (docs/algorithms.md#curtain-corners).
void add_curtain_corners(const TetMesh& mesh, const FrameField& field, const TetLocator& locator,
                         const std::vector<FeatureSeeds>& curves, const std::vector<SnappedPath>& paths,
                         const std::vector<char>& convex, const Points& singular, double h,
                         const BlockOptions& options, std::vector<SheetSource>& sources, BlockDecomposition& out) {
    TraceOptions trace;
    trace.step = options.step * h, trace.stop_distance = options.stop_distance * h, trace.singular_points = singular;
    std::vector<SheetSource> corners = curtain_corner_sources(mesh, field, locator, curves, paths, convex, h, trace);
    out.curtain_corners = int(corners.size());
    mute_jumps_near_corners(sources, corners, kMuteReach * h);
    sources.insert(sources.end(), corners.begin(), corners.end());
}

// Staircase cleaning, then (with `merge`) the few tets it can cut off a block merged into a
// neighbour, and the staircase cleaned again where that happened; `merged` counts those pieces.
Eigen::VectorXi clean_labels(const TetMesh& mesh, const TetTopology& topo, Eigen::VectorXi lab,
                             const BlockOptions& options, bool merge, int& merged) {
    lab = clean_staircase(mesh, topo, std::move(lab));
    if (!merge) return lab;
    const Eigen::VectorXi before = lab;
    const int m = merge_small_pieces(topo, lab, small_piece_tets(mesh.num_tets(), options));
    merged += m + (m == 0 && lab != before);  // a block in two big pieces is two blocks now
    return m > 0 ? clean_staircase(mesh, topo, std::move(lab)) : lab;
}

// Cut edges from the sheets and the singular-curve tubes, the vertex partition, its cleaning,
// then validation with the lens rounds (docs/algorithms.md#partition).
Validated partition_and_validate(const TetMesh& mesh, const TetTopology& topo, const Points& singular,
                                 const std::vector<int>& group, double h, const BlockOptions& options,
                                 BlockDecomposition& out, bool merge, int& merged) {
    const auto t1 = Clock::now();
    std::vector<char> cut = cut_by_sheets(mesh, topo, out.sheets, options.threads);
    cut_near_polylines(mesh, topo, singular, options.tube_radius * h, cut);
    out.stats.cut_edges = int(std::count(cut.begin(), cut.end(), 1));
    out.tet_block = clean_labels(mesh, topo, partition_tets(mesh, topo, cut, options), options, merge, merged);
    out.count = compact_labels(out.tet_block);
    out.seconds_partition += since(t1);
    const auto t2 = Clock::now();
    Validated v = validate_blocks(mesh, topo, group, h, options, out);
    for (int round = 0; round < options.lens_rounds && merge_lenses(v.shared, out); ++round) {
        out.tet_block = clean_labels(mesh, topo, out.tet_block, options, merge, merged);
        out.count = compact_labels(out.tet_block);
        v = validate_blocks(mesh, topo, group, h, options, out);
    }
    out.seconds_validation += since(t2);
    return v;
}

// `more`'s triangles and sources after `soup`'s.
void append_sheets(SheetSoup& soup, const SheetSoup& more) {
    const Eigen::Index np = soup.points.rows(), nt = soup.triangles.rows();
    const int ns = int(soup.source_kind.size());
    soup.points.conservativeResize(np + more.points.rows(), 3);
    soup.points.bottomRows(more.points.rows()) = more.points;
    soup.triangles.conservativeResize(nt + more.triangles.rows(), 3);
    soup.triangles.bottomRows(more.triangles.rows()) = more.triangles.array() + int(np);
    soup.source.conservativeResize(nt + more.source.size());
    soup.source.tail(more.source.size()) = more.source.array() + ns;
    soup.source_kind.insert(soup.source_kind.end(), more.source_kind.begin(), more.source_kind.end());
}

// Neighbour pairs and the counts over blocks and pairs.
void count_conformity(const Validated& v, double h, const BlockOptions& options, BlockDecomposition& out) {
    out.neighbour_pairs = check_conformity(v.faces, options.conform_tolerance * h);
    out.valid = out.flat_edges = out.flat_corners = out.conforming_pairs = 0;
    for (const BlockInfo& b : out.blocks)
        out.valid += b.valid, out.flat_edges += b.flat_edges, out.flat_corners += b.flat_corners;
    out.pairs = int(out.neighbour_pairs.size());
    for (const BlockPair& p : out.neighbour_pairs) out.conforming_pairs += p.conforming;
}

// Better blocks: all valid and conforming, then valid minus invalid, then conforming minus other pairs.
std::tuple<bool, int, int> score(const BlockDecomposition& b) {
    return {b.valid == b.count && b.conforming_pairs == b.pairs, 2 * b.valid - b.count, 2 * b.conforming_pairs - b.pairs};
}

// Partition, validation and conformity of the sheets in `out`. Where merging the pieces that the
// staircase cleaning cut off changed the blocks, they are made again without it and the better
// kept (on a tie, the merged ones): on 2 of the 33 part-size runs it changed, the merge lost a
// valid block (HexMe s05o and n05o at 1 x).
Validated partition_best(const TetMesh& mesh, const TetTopology& topo, const Points& singular,
                         const std::vector<int>& group, double h, const BlockOptions& options, BlockDecomposition& out) {
    BlockDecomposition plain = out;
    const double partition0 = out.seconds_partition, validation0 = out.seconds_validation;
    int merged = 0;
    Validated v = partition_and_validate(mesh, topo, singular, group, h, options, out, true, merged);
    count_conformity(v, h, options, out);
    if (merged == 0) return v;
    int unused = 0;
    Validated w = partition_and_validate(mesh, topo, singular, group, h, options, plain, false, unused);
    count_conformity(w, h, options, plain);
    // Both tries' time: each copy started from the same earlier time.
    const double seconds_partition = out.seconds_partition + plain.seconds_partition - partition0,
                 seconds_validation = out.seconds_validation + plain.seconds_validation - validation0;
    if (score(plain) > score(out)) out = std::move(plain), v = std::move(w);
    out.seconds_partition = seconds_partition, out.seconds_validation = seconds_validation;
    return v;
}

// The surface groups across the ignored imprints, the ambiguous edges the blocks joined and `more`.
std::vector<int> joined_groups(const TetMesh& mesh, const TetTopology& topo, const FeatureSet& features,
                               const std::vector<SnappedPath>& paths, const BlockDecomposition& out, int more = -1) {
    std::vector<int> joined = out.ignored_imprints;
    joined.insert(joined.end(), out.joined_edges.begin(), out.joined_edges.end());
    if (more >= 0) joined.push_back(more);
    std::sort(joined.begin(), joined.end());
    return surface_groups(mesh, topo, features, joined, paths);
}

// How far the invalid blocks are from a hexahedron: faces, edges and corners off 6, 12 and 8.
int hex_defect(const BlockDecomposition& b) {
    int d = 0;
    for (const BlockInfo& i : b.blocks)
        if (!i.valid) d += std::abs(i.faces - 6) + std::abs(i.edges - 12) + std::abs(i.corners - 8);
    return d;
}

// Block faces across ambiguous feature curves (docs/algorithms.md#block-faces-across-ambiguous-edges):
// a chamfer is folded into one of its two neighbouring faces, never both. Greedy, one curve at a
// time in id order: a curve is joined when the blocks then score better, or as well with fewer
// faces, edges and corners off a hexahedron's. The partition stays; only the faces change.
void join_ambiguous_edges(const TetMesh& mesh, const TetTopology& topo, const FeatureSet& features,
                          const std::vector<SnappedPath>& paths, double h, const BlockOptions& options,
                          BlockDecomposition& out, Validated& v) {
    auto better = [](const BlockDecomposition& a, const BlockDecomposition& b) {
        return std::tuple(score(a), -hex_defect(a)) > std::tuple(score(b), -hex_defect(b));
    };
    for (const EdgeFeature& e : features.edges) {
        if (!ambiguous_edge(e) || out.valid == out.count) continue;
        BlockDecomposition tried = out;
        tried.joined_edges.push_back(e.edge);
        Validated w = validate_blocks(mesh, topo, joined_groups(mesh, topo, features, paths, out, e.edge), h, options, tried);
        count_conformity(w, h, options, tried);
        if (better(tried, out)) out = std::move(tried), v = std::move(w);
    }
}

// Invalid blocks of fewer than 6 faces, smallest first: wedges and slivers a sheet cut off a
// block (no hexahedron has fewer faces).
std::vector<int> under_faced_blocks(const BlockDecomposition& out) {
    std::vector<int> under;
    for (int b = 0; b < out.count; ++b)
        if (!out.blocks[b].valid && out.blocks[b].faces < 6 && !out.blocks[b].neighbours.empty()) under.push_back(b);
    std::sort(under.begin(), under.end(), [&](int a, int b) { return out.blocks[a].volume < out.blocks[b].volume; });
    return under;
}

int tet_across(const TetTopology& topo, int f, int t) {
    return topo.face_tets(f, 0) == t ? topo.face_tets(f, 1) : topo.face_tets(f, 0);
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

// Block ids of `out` and of `tried` (out with `from` joined to `into`) mapped both ways; the
// joined block has no earlier counterpart.
EarlierBlocks map_earlier(const BlockDecomposition& out, const Validated& v, const BlockDecomposition& tried, int from,
                          int into) {
    EarlierBlocks earlier{out, v, std::vector<int>(tried.count, -1), std::vector<int>(out.count, -1)};
    for (int b = 0; b < out.count; ++b) {
        const int n = tried.tet_block[out.blocks[b].tets.front()];
        earlier.new_of_old[b] = n;
        if (b != from && b != into) earlier.old_of_new[n] = b;
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

// `out` relabelled as `labels` (block `from` moved into a neighbour), cleaned where `near`
// flags and validated again; none when a block that took its tets is no hexahedron.
std::optional<std::pair<BlockDecomposition, Validated>> relabelled_blocks(
    const TetMesh& mesh, const TetTopology& topo, const std::vector<int>& group, double h, const BlockOptions& options,
    const BlockDecomposition& out, const Validated& v, Eigen::VectorXi labels, const std::vector<char>& near, int from,
    int into) {
    BlockDecomposition tried = out;
    tried.tet_block = clean_staircase(mesh, topo, std::move(labels), near);
    tried.count = compact_labels(tried.tet_block);
    const int m = into >= 0 ? tried.tet_block[out.blocks[into].tets.front()] : -1;
    Validated w = collect_boundaries(mesh, topo, group, tried);
    if (m >= 0) {
        BlockInfo joined;
        validate_block(mesh, w.surface[m], h, options, joined);
        if (!joined.valid && joined.faces < 6) return std::nullopt;  // dissolving contacts only removes faces
    }
    const EarlierBlocks earlier = map_earlier(out, v, tried, from, into);  // the others keep their results
    validate_collected(mesh, h, options, tried, w, &earlier);
    // Every block that took `from`'s tets must be a hexahedron: merging an invalid block into
    // another invalid one would score better and help nobody (a ring's pieces back into a ring).
    for (int t : out.blocks[from].tets)
        if (!tried.blocks[tried.tet_block[t]].valid) return std::nullopt;
    count_conformity(w, h, options, tried);
    return std::pair{std::move(tried), std::move(w)};
}

// `out` with block `from` joined to block `into`; none when the joined block is no hexahedron.
std::optional<std::pair<BlockDecomposition, Validated>> joined_blocks(const TetMesh& mesh, const TetTopology& topo,
                                                       const std::vector<int>& group, double h,
                                                       const BlockOptions& options, const BlockDecomposition& out,
                                                       const Validated& v, int from, int into) {
    if (hopeless_join(mesh, topo, group, h, options, out, from, into)) return std::nullopt;
    Eigen::VectorXi labels = out.tet_block;
    for (int t : out.blocks[from].tets) labels[t] = into;
    std::vector<char> near = near_blocks(out, from);
    for (int n : out.blocks[into].neighbours) near[n] = 1;
    return relabelled_blocks(mesh, topo, group, h, options, out, v, std::move(labels), near, from, into);
}

// A pair of blocks named by their first tets and sizes, so that a try that failed is not
// repeated while both blocks stay as they were.
using BlockPairName = std::tuple<int, int, int, int>;
BlockPairName pair_name(const BlockDecomposition& out, int b, int o) {
    return {out.blocks[b].tets.front(), int(out.blocks[b].tets.size()), out.blocks[o].tets.front(),
            int(out.blocks[o].tets.size())};
}

// One join of an under-faced block to a neighbour that gives better blocks, into `out`. False if none does.
bool join_one(const TetMesh& mesh, const TetTopology& topo, const std::vector<int>& group, double h,
              const BlockOptions& options, BlockDecomposition& out, Validated& v, std::set<BlockPairName>& failed) {
    for (int b : under_faced_blocks(out))
        for (int o : out.blocks[b].neighbours) {
            const BlockPairName name = pair_name(out, b, o);
            if (failed.count(name)) continue;
            auto tried = joined_blocks(mesh, topo, group, h, options, out, v, b, o);
            if (!tried || !(score(tried->first) > score(out))) {
                failed.insert(name);
                continue;
            }
            out = std::move(tried->first), v = std::move(tried->second), ++out.joined_blocks;
            return true;
        }
    return false;
}

// Under-faced blocks join a neighbour (docs/algorithms.md#under-faced-blocks) when the two make
// a hexahedron and the blocks score better. Greedy, one join per round.
void join_under_faced(const TetMesh& mesh, const TetTopology& topo, const FeatureSet& features,
                      const std::vector<SnappedPath>& paths, double h, const BlockOptions& options,
                      BlockDecomposition& out, Validated& v) {
    const std::vector<int> group = joined_groups(mesh, topo, features, paths, out);
    const std::vector<char> trouble = tets_in_trouble(out);
    std::set<BlockPairName> failed;
    for (int round = 0; round < options.join_rounds && join_one(mesh, topo, group, h, options, out, v, failed); ++round) {
    }
    if (out.joined_blocks > 0) out.trouble_before_joins = trouble;
}

bool has_junction(const std::vector<SheetSource>& sources) {
    for (const SheetSource& s : sources)
        if (s.junction[0] >= 0 || s.junction[1] >= 0) return true;
    return false;
}

// The configured mode first; with try_junctions and a junction node in the graph, the others
// (those that zip only where a curve runs straight on through the node). Older modes come first,
// so that on a tie their blocks stay.
std::vector<BlockOptions::Junctions> junction_modes(const std::vector<SheetSource>& sources, const BlockOptions& o) {
    using J = BlockOptions::Junctions;
    std::vector<J> modes{o.junctions};
    if (!o.try_junctions || !has_junction(sources)) return modes;
    const bool straight = has_straight_junction(sources);
    for (J m : {J::Continue, J::Drop, J::DropAndClose, J::DropAndZip, J::DropCloseAndZip, J::ContinueAndClose})
        if (m != o.junctions && (straight || (m != J::DropAndZip && m != J::DropCloseAndZip))) modes.push_back(m);
    return modes;
}

const char* junction_name(BlockOptions::Junctions m) {
    switch (m) {
        case BlockOptions::Junctions::Continue: return "continue";
        case BlockOptions::Junctions::Drop: return "drop";
        case BlockOptions::Junctions::DropAndClose: return "drop+close";
        case BlockOptions::Junctions::DropAndZip: return "drop+zip";
        case BlockOptions::Junctions::DropCloseAndZip: return "drop+close+zip";
        case BlockOptions::Junctions::ContinueAndClose: return "continue+close";
    }
    return "";
}

// Sheets, partition and validation once per junction mode (junction_modes); `out` (holding what
// the tries share) becomes the best try by score, with every try listed when the graph has a
// junction node.
Validated best_junction_mode(const TetMesh& mesh, const TetTopology& topo, const FrameField& field,
                             const TetLocator& locator, const std::vector<SheetSource>& sources, const Points& singular,
                             const std::vector<int>& group, double h, const BlockOptions& options,
                             BlockDecomposition& out) {
    Validated v;
    const BlockDecomposition common = out;
    const std::vector<BlockOptions::Junctions> modes = junction_modes(sources, options);
    double sheet_seconds = 0;
    std::vector<BlockDecomposition::JunctionTry> tries;
    for (size_t i = 0; i < modes.size(); ++i) {
        BlockOptions o = options;
        o.junctions = modes[i];
        BlockDecomposition tried = common;
        const auto t1 = Clock::now();
        tried.sheets = build_sheets(mesh, field, locator, sources, singular, h, o, tried.stats);
        sheet_seconds += since(t1);
        Validated w = partition_best(mesh, topo, singular, group, h, o, tried);
        tries.push_back({junction_name(modes[i]), tried.count, tried.valid, tried.pairs, tried.conforming_pairs});
        if (i == 0 || score(tried) > score(out)) out = std::move(tried), v = std::move(w), out.junction_mode = junction_name(modes[i]);
    }
    if (has_junction(sources)) out.junction_tries = std::move(tries);
    else out.junction_mode.clear();
    out.seconds_sheets = sheet_seconds;
    return v;
}

// What every partition of one build_blocks call shares.
struct BlockInputs {
    const TetMesh& mesh;
    const TetTopology& topo;
    const FeatureSet& features;
    const FrameField& field;
    const TetLocator& locator;
    const std::vector<SnappedPath>& paths;
    const std::vector<int>& group;  // surface_groups
    double h;
    const BlockOptions& options;
};

// Sheets from `sources`, partition and validation in each junction mode, rings cut where that
// helps, ambiguous edges joined: `out`, holding what the tries share, becomes the best blocks.
Validated blocks_from_sources(const BlockInputs& in, const std::vector<SheetSource>& sources, const Points& singular,
                              BlockDecomposition& out) {
    Validated v = best_junction_mode(in.mesh, in.topo, in.field, in.locator, sources, singular, in.group, in.h,
                                     in.options, out);
    // Rings (a tube): no sheet above cuts them across; meridian sheets do, then all again, kept
    // only when the blocks are better (on HexMe's n10o at 0.7 x they were not).
    TraceOptions trace;
    trace.step = in.options.step * in.h, trace.stop_distance = in.options.stop_distance * in.h;
    trace.singular_points = singular;
    const std::vector<SheetSource> rings = ring_sources(in.mesh, in.field, in.locator, out, v.surface, in.h, trace);
    if (!rings.empty()) {
        BlockDecomposition cut = out;
        const auto t3 = Clock::now();
        append_sheets(cut.sheets, build_sheets(in.mesh, in.field, in.locator, rings, singular, in.h, in.options, cut.stats));
        cut.ring_cuts = int(rings.size());
        cut.seconds_sheets += since(t3);
        Validated w = partition_best(in.mesh, in.topo, singular, in.group, in.h, in.options, cut);
        if (score(cut) > score(out)) out = std::move(cut), v = std::move(w);
    }
    join_ambiguous_edges(in.mesh, in.topo, in.features, in.paths, in.h, in.options, out, v);
    join_under_faced(in.mesh, in.topo, in.features, in.paths, in.h, in.options, out, v);
    return v;
}

// The curves glued to ambiguous edges as sheet sources too (docs/algorithms.md#sheets-from-glued-curves):
// the blocks made from `common` with them replace `out` when they score better.
void try_glued_sources(const BlockInputs& in, const SingularityGraph& graph, const std::vector<SheetSource>& sources,
                       const Points& singular, const BlockDecomposition& common, BlockDecomposition& out, Validated& v) {
    std::vector<SheetSource> more = sources;
    const std::vector<SheetSource> glued = glued_sources(in.mesh, in.field, graph, in.locator, in.h, in.options);
    more.insert(more.end(), glued.begin(), glued.end());
    SingularityGraph absorbed;
    absorbed.curves = graph.absorbed;
    const Points glued_points = singular_points(absorbed);
    Points all(singular.rows() + glued_points.rows(), 3);
    all << singular, glued_points;
    BlockDecomposition with = common;
    Validated w = blocks_from_sources(in, more, all, with);
    with.glued_sources = int(glued.size());
    if (score(with) > score(out)) out = std::move(with), v = std::move(w);
}

}  // namespace

// Per tet: whether its block is invalid or in a non-conforming pair.
std::vector<char> tets_in_trouble(const BlockDecomposition& out) {
    std::vector<char> block(out.count, 0), tet(out.tet_block.size(), 0);
    for (int b = 0; b < out.count; ++b) block[b] = !out.blocks[b].valid;
    for (const BlockPair& p : out.neighbour_pairs)
        if (!p.conforming) block[p.a] = block[p.b] = 1;
    for (int t = 0; t < int(tet.size()); ++t) tet[t] = block[out.tet_block[t]];
    return tet;
}

BlockDecomposition build_blocks(const TetMesh& mesh, const TetTopology& topo, const FeatureSet& features,
                                const FrameField& field, const SingularityGraph& graph,
                                const std::vector<SnappedPath>& paths, const BlockOptions& options) {
    check_inputs(mesh, topo, field, graph);
    const auto t0 = Clock::now();
    BlockDecomposition out;
    const double h = mean_edge_length(mesh, topo, 1);
    out.h = h;
    const TetLocator locator(mesh, topo);

    // Sheets.
    std::vector<SheetSource> sources = singular_sources(mesh, field, graph, locator, h, options);
    const std::vector<int> imprints = followed_imprints(mesh, features, field);
    for (const EdgeFeature& e : features.edges)
        if (e.valence == 2 && !ambiguous_edge(e) && !std::binary_search(imprints.begin(), imprints.end(), e.edge))
            out.ignored_imprints.push_back(e.edge);
    std::sort(out.ignored_imprints.begin(), out.ignored_imprints.end());
    const std::vector<char> convex = convex_paths(mesh, features, paths, h);
    for (int i = 0; i < int(convex.size()); ++i)
        if (convex[i]) out.convex_paths.push_back(i);
    std::vector<int> edges = imprints;  // the followed imprints and the concave curves
    for (const EdgeFeature& e : features.edges)
        if (e.valence == 3) edges.push_back(e.edge);
    const std::vector<FeatureSeeds> curves = feature_seeds(mesh, features, field, edges);
    std::vector<SheetSource> feature = feature_sources(mesh, features, field, curves, paths, convex);
    sources.insert(sources.end(), feature.begin(), feature.end());
    const Points singular = singular_points(graph);
    if (options.curtain_corners) add_curtain_corners(mesh, field, locator, curves, paths, convex, singular, h, options, sources, out);
    const std::vector<int> group = surface_groups(mesh, topo, features, out.ignored_imprints, paths);

    // Sheets, partition and validation (lenses join a neighbour and the blocks are validated
    // again), once per junction mode tried; the best blocks are kept.
    const double source_seconds = since(t0);
    const BlockDecomposition common = out;
    const BlockInputs in{mesh, topo, features, field, locator, paths, group, h, options};
    Validated v = blocks_from_sources(in, sources, singular, out);
    if (options.try_glued && !graph.absorbed.empty()) try_glued_sources(in, graph, sources, singular, common, out, v);
    out.seconds_sheets += source_seconds;
    out.surfaces = block_surfaces(mesh, v.surface, v.faces);
    out.boundary = std::move(v.surface);
    out.faces = std::move(v.faces);
    out.seconds = since(t0);
    return out;
}

}  // namespace framefix
