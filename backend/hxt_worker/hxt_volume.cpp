// One discrete gmsh surface per B-rep face, one volume bounded by them, Mesh.Algorithm3D = 10.
// gmsh does not change a discrete surface's mesh while meshing the volume, so the boundary, its
// tags and the feature segments are the input's (checked).
#include "hxt_volume.h"

#include <algorithm>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

#include <gmsh.h>

#include "framefix/core/error.h"
#include "framefix/hxt/hxt_protocol.h"
#include "framefix/mesh/keys.h"

namespace framefix::hxt {
namespace {

constexpr int kHxtAlgorithm = 10;       // gmsh's Mesh.Algorithm3D value for HXT
constexpr int kTriangle = 2, kTet = 4;  // gmsh element types
// gmsh sizes the interior from the surface's edges, and HXT's edges come out longer than the
// size asked: at 1 x the mean edge is 1.10-1.15 h. 0.83 gives 0.98-0.99 h on the samples, as
// TetGen does (docs/results.md), so that a size means the same density with both meshers.
constexpr double kHxtSizeFactor = 0.83;

// Surface point i is gmsh node i + 1, added to the first face that uses it (a node belongs to
// one entity; triangles of other faces may still use it).
void add_surface(const SurfaceMesh& s) {
    std::map<int, std::vector<std::size_t>> triangles;  // face tag -> node tags, 3 per triangle
    for (Eigen::Index t = 0; t < s.triangles.rows(); ++t)
        for (int k = 0; k < 3; ++k) triangles[s.face_tags(t)].push_back(std::size_t(s.triangles(t, k)) + 1);
    std::vector<int> owner(size_t(s.points.rows()), 0);
    for (const auto& [tag, nodes] : triangles) {
        gmsh::model::addDiscreteEntity(2, tag);
        for (std::size_t n : nodes)
            if (!owner[n - 1]) owner[n - 1] = tag;
    }
    std::map<int, std::pair<std::vector<std::size_t>, std::vector<double>>> nodes;
    for (Eigen::Index p = 0; p < s.points.rows(); ++p) {
        if (!owner[size_t(p)]) throw Error("mesh", "surface point " + std::to_string(p) + " is on no triangle");
        auto& [tags, xyz] = nodes[owner[size_t(p)]];
        tags.push_back(std::size_t(p) + 1);
        for (int k = 0; k < 3; ++k) xyz.push_back(s.points(p, k));
    }
    for (const auto& [tag, n] : nodes) gmsh::model::mesh::addNodes(2, tag, n.first, n.second);
    std::size_t element = 1;
    std::vector<int> faces;
    for (const auto& [tag, t] : triangles) {
        std::vector<std::size_t> ids(t.size() / 3);
        for (std::size_t& id : ids) id = element++;
        gmsh::model::mesh::addElementsByType(tag, kTriangle, ids, t);
        faces.push_back(tag);
    }
    // A discrete volume counts as meshed already; a geo volume on the discrete surfaces is meshed.
    gmsh::model::geo::addVolume({gmsh::model::geo::addSurfaceLoop(faces)});
    gmsh::model::geo::synchronize();
}

// gmsh node tag -> vertex: surface point i is tag i + 1, interior nodes follow in gmsh's order.
std::vector<int> vertex_of_tag(const std::vector<std::size_t>& tags, int surface_points) {
    const std::size_t max_tag = tags.empty() ? 0 : *std::max_element(tags.begin(), tags.end());
    if (max_tag > 4 * tags.size() + 16) throw Error("mesh", "gmsh numbered the nodes sparsely");
    std::vector<int> index(max_tag + 1, -1);
    int next = surface_points;
    for (std::size_t tag : tags) index[tag] = tag <= std::size_t(surface_points) ? int(tag) - 1 : next++;
    return index;
}

TetMesh read_volume(const SurfaceMesh& s) {
    std::vector<std::size_t> tags, element_tags, tet_nodes;
    std::vector<double> xyz, uvw;
    gmsh::model::mesh::getNodes(tags, xyz, uvw, -1, -1, false, false);
    const int surface_points = int(s.points.rows());
    const std::vector<int> index = vertex_of_tag(tags, surface_points);
    TetMesh mesh;
    mesh.points.resize(Eigen::Index(tags.size()), 3);
    mesh.points.topRows(surface_points) = s.points;
    for (std::size_t i = 0; i < tags.size(); ++i)
        if (const int v = index[tags[i]]; v >= surface_points)
            for (int k = 0; k < 3; ++k) mesh.points(v, k) = xyz[3 * i + k];
    gmsh::model::mesh::getElementsByType(kTet, element_tags, tet_nodes);
    mesh.tets.resize(Eigen::Index(element_tags.size()), 4);
    for (int t = 0; t < mesh.num_tets(); ++t) {
        for (int k = 0; k < 4; ++k) {
            const std::size_t tag = tet_nodes[4 * size_t(t) + k];
            if (tag >= index.size() || index[tag] < 0) throw Error("mesh", "a tet from HXT names an unknown node");
            mesh.tets(t, k) = index[tag];
        }
        if (tet_volume(mesh, t) < 0) std::swap(mesh.tets(t, 2), mesh.tets(t, 3));
    }
    return mesh;
}

// Throws unless every surface triangle is the face of exactly one tet: HXT kept the boundary.
void check_boundary(const TetMesh& mesh, const SurfaceMesh& s) {
    std::unordered_map<TriangleKey, int, TriangleKeyHash> seen;
    seen.reserve(size_t(s.triangles.rows()) * 2);
    for (Eigen::Index t = 0; t < s.triangles.rows(); ++t)
        seen.emplace(triangle_key(s.triangles(t, 0), s.triangles(t, 1), s.triangles(t, 2)), 0);
    const int surface_points = int(s.points.rows());
    for (int t = 0; t < mesh.num_tets(); ++t)
        for (const auto& f : kTetFace) {
            const int a = mesh.tets(t, f[0]), b = mesh.tets(t, f[1]), c = mesh.tets(t, f[2]);
            if (a >= surface_points || b >= surface_points || c >= surface_points) continue;  // not on the surface
            if (const auto it = seen.find(triangle_key(a, b, c)); it != seen.end()) ++it->second;
        }
    const auto bad = std::count_if(seen.begin(), seen.end(), [](const auto& kv) { return kv.second != 1; });
    if (bad > 0)
        throw Error("mesh", "HXT did not keep the surface: " + std::to_string(bad) + " of " +
                                std::to_string(s.triangles.rows()) + " boundary triangles are not the face of one tet");
}

std::string last_error(const char* fallback) {
    std::string text;
    try {
        gmsh::logger::getLastError(text);
    } catch (...) {
    }
    return "HXT failed: " + (text.empty() ? std::string(fallback) : text);
}

}  // namespace

std::string mesh_volume(const SurfaceMesh& s, double h, int threads) {
    if (!(h > 0)) throw Error("mesh", "the size must be positive");
    gmsh::initialize(0, nullptr, false);
    TetMesh mesh;
    std::string failure;
    try {
        gmsh::option::setNumber("General.Terminal", 0);
        gmsh::option::setNumber("General.Verbosity", 0);  // formatting gmsh's messages showed in the profile
        gmsh::option::setNumber("General.NumThreads", std::max(1, threads));
        gmsh::option::setNumber("Mesh.Algorithm3D", kHxtAlgorithm);
        gmsh::option::setNumber("Mesh.MeshSizeFactor", kHxtSizeFactor);
        gmsh::option::setNumber("Mesh.MeshSizeMax", h * kHxtSizeFactor);
        gmsh::option::setNumber("Mesh.Renumber", 0);  // surface point i stays node i + 1
        gmsh::model::add("framefix");
        add_surface(s);
        gmsh::model::mesh::generate(3);
        mesh = read_volume(s);
        if (mesh.num_tets() == 0) throw Error("mesh", "HXT produced no tets; the surface may not be closed");
        check_boundary(mesh, s);
    } catch (const Error& e) {
        failure = e.message();
    } catch (...) {
        failure = last_error("no message");
    }
    gmsh::finalize();
    if (!failure.empty()) return kFailed + failure;
    mesh.boundary_faces = s.triangles;
    mesh.face_tags = s.face_tags;
    mesh.feature_edges = s.feature_segments;
    mesh.edge_tags = s.segment_tags;
    mesh.corner_vertices = s.corner_points;
    mesh.size = h;
    return kMeshed + tet_mesh_bytes(mesh);
}

}  // namespace framefix::hxt
