#include <algorithm>
#include <chrono>
#include <set>
#include <unordered_map>

#include <omp.h>

#include "framefix/blocks/blocks.h"
#include "framefix/blocks/partition.h"
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

// CAD surface group of each topology face (-1 inside): B-rep faces joined across boundary edges
// that are not feature curves (e.g. a cylinder's seam), so one block face is not split there.
std::vector<int> surface_groups(const TetMesh& mesh, const TetTopology& topo, const FeatureSet& features) {
    const std::uint64_t nv = mesh.num_vertices();
    auto ekey = [nv](int a, int b) { return edge_key(a, b, nv); };
    std::unordered_map<PairKey, int> feature_edge;
    for (int e = 0; e < int(mesh.feature_edges.rows()); ++e)
        if (features.valence_of(mesh.edge_tags[e]) > 0) feature_edge[ekey(mesh.feature_edges(e, 0), mesh.feature_edges(e, 1))] = 1;
    const int max_tag = mesh.face_tags.size() ? mesh.face_tags.maxCoeff() : 0;
    DisjointSet groups(max_tag + 1);  // merge_into: the group ids are roots, they label block faces
    std::unordered_map<PairKey, int> edge_tag;
    for (int b = 0; b < int(mesh.boundary_faces.rows()); ++b)
        for (int k = 0; k < 3; ++k) {
            const PairKey key = ekey(mesh.boundary_faces(b, k), mesh.boundary_faces(b, (k + 1) % 3));
            auto [it, fresh] = edge_tag.try_emplace(key, mesh.face_tags[b]);
            if (!fresh && it->second != mesh.face_tags[b] && !feature_edge.count(key))
                groups.merge_into(it->second, mesh.face_tags[b]);
        }
    std::unordered_map<TriangleKey, int, TriangleKeyHash> tag_of;  // sorted triangle -> B-rep face
    auto tkey = [](const auto& f) { return triangle_key(f(0), f(1), f(2)); };
    for (int b = 0; b < int(mesh.boundary_faces.rows()); ++b) tag_of[tkey(mesh.boundary_faces.row(b))] = mesh.face_tags[b];
    std::vector<int> group(topo.faces.rows(), -1);
    for (int f = 0; f < int(topo.faces.rows()); ++f) {
        if (topo.face_tets(f, 1) >= 0) continue;
        auto it = tag_of.find(tkey(topo.faces.row(f)));
        group[f] = it == tag_of.end() ? 0 : groups.find(it->second);
    }
    return group;
}

}  // namespace

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
    std::vector<SheetSource> feature = feature_sources(mesh, features, field, paths);
    sources.insert(sources.end(), feature.begin(), feature.end());
    const Points singular = singular_points(graph);
    out.sheets = build_sheets(mesh, field, locator, sources, singular, h, options, out.stats);
    out.seconds_sheets = since(t0);

    // Partition.
    const auto t1 = Clock::now();
    std::vector<char> cut = cut_by_sheets(mesh, topo, out.sheets, options.threads);
    cut_near_polylines(mesh, topo, singular, options.tube_radius * h, cut);
    out.stats.cut_edges = int(std::count(cut.begin(), cut.end(), 1));
    out.tet_block = clean_staircase(mesh, topo, partition_tets(mesh, topo, cut, options));
    out.count = compact_labels(out.tet_block);
    out.seconds_partition = since(t1);

    // Validation.
    const auto t2 = Clock::now();
    const std::vector<int> group = surface_groups(mesh, topo, features);
    std::vector<std::vector<BoundaryTriangle>> surface(out.count);
    out.blocks.assign(out.count, BlockInfo{});
    std::vector<std::set<int>> neighbours(out.count);
    for (int f = 0; f < int(topo.faces.rows()); ++f) {
        const int ta = topo.face_tets(f, 0), tb = topo.face_tets(f, 1);
        const int la = out.tet_block[ta], lb = tb >= 0 ? out.tet_block[tb] : -1;
        if (la == lb) continue;
        for (int side = 0; side < 2; ++side) {
            const int t = side == 0 ? ta : tb, b = side == 0 ? la : lb, other = side == 0 ? lb : la;
            if (b < 0) continue;
            BoundaryTriangle tri;
            tri.verts = topo.faces.row(f).transpose();
            tri.label = other >= 0 ? other : -1 - group[f];
            const Eigen::Vector3d p0 = mesh.points.row(tri.verts[0]).transpose();
            tri.normal = (mesh.points.row(tri.verts[1]).transpose() - p0).cross(mesh.points.row(tri.verts[2]).transpose() - p0);
            Eigen::Vector3d inner = Eigen::Vector3d::Zero();
            for (int k = 0; k < 4; ++k) inner += mesh.points.row(mesh.tets(t, k)).transpose() / 4;
            if (tri.normal.dot(p0 - inner) < 0) tri.normal = -tri.normal;
            surface[b].push_back(tri);
            if (other >= 0) neighbours[b].insert(other);
        }
    }
    for (int t = 0; t < mesh.num_tets(); ++t) {
        BlockInfo& info = out.blocks[out.tet_block[t]];
        info.tets.push_back(t);
        info.volume += tet_volume(mesh, t);
    }
    std::vector<BlockFaces> faces(out.count);
#pragma omp parallel for schedule(dynamic, 1) num_threads(options.threads > 0 ? options.threads : omp_get_max_threads())
    for (int b = 0; b < out.count; ++b) {
        BlockInfo& info = out.blocks[b];
        faces[b] = validate_block(mesh, surface[b], h, options, info);
        info.neighbours.assign(neighbours[b].begin(), neighbours[b].end());
        std::set<int> verts;
        for (int t : info.tets) for (int k = 0; k < 4; ++k) verts.insert(mesh.tets(t, k));
        for (int v : verts) info.centroid += mesh.points.row(v).transpose() / double(verts.size());
    }
    out.neighbour_pairs = check_conformity(faces, options.conform_tolerance * h);
    for (const BlockInfo& b : out.blocks)
        out.valid += b.valid, out.flat_edges += b.flat_edges, out.flat_corners += b.flat_corners;
    out.pairs = int(out.neighbour_pairs.size());
    for (const BlockPair& p : out.neighbour_pairs) out.conforming_pairs += p.conforming;
    out.seconds_validation = since(t2);
    out.seconds = since(t0);
    return out;
}

}  // namespace framefix
