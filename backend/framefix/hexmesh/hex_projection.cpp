#include "framefix/hexmesh/hex_projection.h"

#include <algorithm>
#include <cmath>
#include <limits>
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
    stride = std::uint64_t(mesh.num_vertices());
    for (int e = 0; e < int(mesh.feature_edges.rows()); ++e) {
        for (int k = 0; k < 2; ++k) edge_tag[mesh.feature_edges(e, k)] = mesh.edge_tags[e];
        segment_tag[edge_key(mesh.feature_edges(e, 0), mesh.feature_edges(e, 1), stride)] = mesh.edge_tags[e];
    }
}

EdgeSupport edge_support(const TetMesh& mesh, const ComplexEdge& edge, const SurfaceLocator& at) {
    EdgeSupport s;
    const int n = int(edge.chain.size());
    s.chain.resize(n, 3);
    std::vector<int> curves, faces;
    int on_curve = 0, on_boundary = 0;
    for (int i = 0; i < n; ++i) {
        const int v = edge.chain[size_t(i)];
        s.chain.row(i) = mesh.points.row(v);
        on_boundary += at.face_tag[v] > 0;
        faces.push_back(at.face_tag[v]);
        if (i + 1 == n) continue;
        // The segment's own B-rep edge: at a B-rep vertex the per-vertex tag names just one of
        // its curves (an imprint ending on the edge pulled points onto the imprint).
        const auto it = at.segment_tag.find(edge_key(v, edge.chain[size_t(i + 1)], at.stride));
        const int tag = it == at.segment_tag.end() ? 0 : it->second;
        on_curve += tag > 0;
        curves.push_back(tag);
    }
    if (n >= 2 && 2 * on_curve >= n - 1) s.kind = EdgeSupport::curve, s.tags = curves;
    else if (2 * on_boundary >= n) s.kind = EdgeSupport::face, s.tags = faces;
    return s;
}

Eigen::Vector3d project_on_support(const Eigen::Vector3d& p, const EdgeSupport& s, const CadProjector& cad) {
    if (s.kind == EdgeSupport::inside || s.chain.rows() == 0) return p;
    int best = 0;
    double nearest = 1e300;
    const bool curve = s.kind == EdgeSupport::curve;
    for (int i = 0; i + (curve ? 1 : 0) < int(s.chain.rows()); ++i) {
        const Eigen::Vector3d a = s.chain.row(i).transpose();
        double d = (p - a).squaredNorm();
        if (curve) {
            const Eigen::Vector3d ab = s.chain.row(i + 1).transpose() - a;
            const double f = ab.squaredNorm() > 0 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0;
            d = (p - a - f * ab).squaredNorm();
        }
        if (s.tags[size_t(i)] > 0 && d < nearest) nearest = d, best = s.tags[size_t(i)];
    }
    if (best > 0 && curve && cad.to_edge) return cad.to_edge(best, p);
    if (best > 0 && !curve && cad.to_face) return cad.to_face(best, p);
    return p;
}

Eigen::Vector3d project_corner(const TetMesh& mesh, const ComplexCorner& corner, const SurfaceLocator& at,
                               const CadProjector& cad) {
    for (int i = 0; i < int(mesh.corner_vertices.size()); ++i)
        if (std::binary_search(corner.vertices.begin(), corner.vertices.end(), mesh.corner_vertices[i])) return corner.position;
    std::vector<int> curves, faces;
    for (int v : corner.vertices) curves.push_back(at.edge_tag[v]), faces.push_back(at.face_tag[v]);
    if (mode(curves) > 0 && cad.to_edge) return cad.to_edge(mode(curves), corner.position);
    if (mode(faces) > 0 && cad.to_face) return cad.to_face(mode(faces), corner.position);
    return corner.position;
}

FaceProjector::FaceProjector(const TetMesh& mesh, const ComplexFace& face, const SurfaceLocator& at) : boundary_(face.boundary) {
    // A boundary face's patch may hold a few interface triangles the patch cleaning merged into
    // it; its points go onto the part's own triangles only.
    for (int pass = 0; pass < 2 && tris_.empty(); ++pass)
        for (const Eigen::Vector3i& t : face.triangles) {
            const auto it = at.triangle_tag.find(triangle_key(t[0], t[1], t[2]));
            const int tag = it == at.triangle_tag.end() ? 0 : it->second;
            if (pass == 0 && boundary_ && tag == 0) continue;
            tris_.push_back({mesh.points.row(t[0]).transpose(), mesh.points.row(t[1]).transpose(), mesh.points.row(t[2]).transpose()});
            tags_.push_back(tag);
        }
    Points centroids(Eigen::Index(tris_.size()), 3);
    double edges = 0;
    for (size_t i = 0; i < tris_.size(); ++i) {
        const Eigen::Vector3d c = (tris_[i][0] + tris_[i][1] + tris_[i][2]) / 3;
        centroids.row(Eigen::Index(i)) = c.transpose();
        for (int k = 0; k < 3; ++k) reach_ = std::max(reach_, (tris_[i][k] - c).norm()), edges += (tris_[i][k] - tris_[i][(k + 1) % 3]).norm();
    }
    if (tris_.empty()) return;
    // Two mean triangle edges, coarser when the grid would have more than 8 cells per triangle
    // (a curved face's box is mostly empty): all faces' grids live at once.
    const Eigen::Vector3d ext = centroids.colwise().maxCoeff() - centroids.colwise().minCoeff();
    cell_ = std::max({2 * edges / (3 * double(tris_.size())), std::cbrt(ext.prod() / (8 * double(tris_.size()))), 1e-12});
    centroids_.emplace(centroids, cell_);
}

// The triangle closest to p, and the closest point q on it: within a radius that doubles until
// a triangle lies inside it (every triangle within r has its centroid within r + reach_).
int FaceProjector::nearest_triangle(const Eigen::Vector3d& p, Eigen::Vector3d& q) const {
    std::vector<int> near;
    for (double r = cell_; centroids_; r *= 2) {
        near.clear();
        centroids_->within(p, r + reach_, near);
        const bool all = near.size() == tris_.size();  // then the closest of them is the answer
        double best = all ? std::numeric_limits<double>::infinity() : r * r;
        int found = -1;
        for (int i : near) {
            const Eigen::Vector3d x = closest_on_triangle(p, tris_[size_t(i)][0], tris_[size_t(i)][1], tris_[size_t(i)][2]);
            const double d = (x - p).squaredNorm();
            if (d < best || (d == best && found >= 0 && i < found)) best = d, q = x, found = i;
        }
        if (found >= 0 || all) return found;
    }
    return -1;
}

Eigen::Vector3d FaceProjector::project(const Eigen::Vector3d& p, const CadProjector& cad, int* tag,
                                       Eigen::Vector3d* normal) const {
    Eigen::Vector3d q = p;
    const int nearest = nearest_triangle(p, q);
    const int best_tag = nearest >= 0 ? tags_[size_t(nearest)] : 0;
    if (tag) *tag = best_tag;
    if (normal && nearest >= 0) {
        const auto& t = tris_[size_t(nearest)];
        *normal = (t[1] - t[0]).cross(t[2] - t[0]).normalized();
    }
    if (boundary_ && best_tag > 0 && cad.to_face) return cad.to_face(best_tag, q);
    return q;
}

}  // namespace framefix
