#include "framefix/hexmesh/hex_projection.h"

#include <algorithm>
#include <map>

#include <Eigen/Geometry>

#include "framefix/corrections/boundary_distance.h"

namespace framefix {

namespace {

// The most frequent positive value, the lowest on ties; 0 when there is none.
int mode(const std::vector<int>& values) {
    std::map<int, int> count;
    for (int v : values) if (v > 0) count[v] += 1;
    int best = 0, most = 0;
    for (auto [v, n] : count) if (n > most) most = n, best = v;
    return best;
}

}  // namespace

SurfaceLocator::SurfaceLocator(const TetMesh& mesh) : face_tag(mesh.num_vertices(), 0), edge_tag(mesh.num_vertices(), 0) {
    for (int b = 0; b < int(mesh.boundary_faces.rows()); ++b) {
        const int tag = mesh.face_tags.size() > b ? mesh.face_tags[b] : 0;
        for (int k = 0; k < 3; ++k) face_tag[mesh.boundary_faces(b, k)] = tag;
        triangle_tag[triangle_key(mesh.boundary_faces(b, 0), mesh.boundary_faces(b, 1), mesh.boundary_faces(b, 2))] = tag;
    }
    for (int e = 0; e < int(mesh.feature_edges.rows()); ++e)
        for (int k = 0; k < 2; ++k) edge_tag[mesh.feature_edges(e, k)] = mesh.edge_tags[e];
}

EdgeSupport edge_support(const ComplexEdge& edge, const SurfaceLocator& at) {
    std::vector<int> curves, faces;
    int on_boundary = 0;
    for (size_t i = 0; i < edge.chain.size(); ++i) {
        const int v = edge.chain[i];
        on_boundary += at.face_tag[v] > 0;
        if (at.face_tag[v] > 0) faces.push_back(at.face_tag[v]);
        // A segment on a feature curve: both ends carry the curve's tag.
        if (i + 1 < edge.chain.size() && at.edge_tag[v] > 0 && at.edge_tag[v] == at.edge_tag[edge.chain[i + 1]])
            curves.push_back(at.edge_tag[v]);
    }
    const int segments = std::max(1, int(edge.chain.size()) - 1);
    if (2 * int(curves.size()) >= segments && mode(curves) > 0) return {EdgeSupport::curve, mode(curves)};
    if (2 * on_boundary >= int(edge.chain.size()) && mode(faces) > 0) return {EdgeSupport::face, mode(faces)};
    return {};
}

Eigen::Vector3d project_on_support(const Eigen::Vector3d& p, const EdgeSupport& support, const CadProjector& cad) {
    if (support.kind == EdgeSupport::curve && cad.to_edge) return cad.to_edge(support.tag, p);
    if (support.kind == EdgeSupport::face && cad.to_face) return cad.to_face(support.tag, p);
    return p;
}

Eigen::Vector3d project_corner(const TetMesh& mesh, const ComplexCorner& corner, const SurfaceLocator& at,
                               const CadProjector& cad) {
    for (int i = 0; i < int(mesh.corner_vertices.size()); ++i)
        if (std::binary_search(corner.vertices.begin(), corner.vertices.end(), mesh.corner_vertices[i])) return corner.position;
    std::vector<int> curves, faces;
    for (int v : corner.vertices) curves.push_back(at.edge_tag[v]), faces.push_back(at.face_tag[v]);
    if (mode(curves) > 0) return project_on_support(corner.position, {EdgeSupport::curve, mode(curves)}, cad);
    if (mode(faces) > 0) return project_on_support(corner.position, {EdgeSupport::face, mode(faces)}, cad);
    return corner.position;
}

FaceProjector::FaceProjector(const TetMesh& mesh, const ComplexFace& face, const SurfaceLocator& at) : boundary_(face.boundary) {
    for (const Eigen::Vector3i& t : face.triangles) {
        tris_.push_back({mesh.points.row(t[0]).transpose(), mesh.points.row(t[1]).transpose(), mesh.points.row(t[2]).transpose()});
        const auto it = at.triangle_tag.find(triangle_key(t[0], t[1], t[2]));
        tags_.push_back(it == at.triangle_tag.end() ? 0 : it->second);
    }
}

Eigen::Vector3d FaceProjector::project(const Eigen::Vector3d& p, const CadProjector& cad, int* tag,
                                       Eigen::Vector3d* normal) const {
    double best = 1e300;
    Eigen::Vector3d q = p;
    int best_tag = 0;
    size_t nearest = 0;
    for (size_t i = 0; i < tris_.size(); ++i) {
        const Eigen::Vector3d x = closest_on_triangle(p, tris_[i][0], tris_[i][1], tris_[i][2]);
        const double d = (x - p).squaredNorm();
        if (d < best) best = d, q = x, best_tag = tags_[i], nearest = i;
    }
    if (tag) *tag = best_tag;
    if (normal && !tris_.empty())
        *normal = (tris_[nearest][1] - tris_[nearest][0]).cross(tris_[nearest][2] - tris_[nearest][0]).normalized();
    if (boundary_ && best_tag > 0 && cad.to_face) return cad.to_face(best_tag, q);
    return q;
}

}  // namespace framefix
