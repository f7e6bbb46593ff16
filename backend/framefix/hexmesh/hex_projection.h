#pragma once
// Putting hex vertices on the part (internal to hexmesh): onto a block face's tet triangles,
// then onto the B-rep face or edge under them.
#include <optional>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "framefix/hexmesh/block_structure.h"
#include "framefix/hexmesh/hexmesh.h"
#include "framefix/mesh/keys.h"
#include "framefix/streamlines/point_grid.h"

namespace framefix {

// Per mesh vertex: a B-rep face tag of a boundary triangle at it (0 inside) and a B-rep edge tag
// of a feature edge at it (0 off the feature curves; a B-rep vertex has several, this is one);
// per boundary triangle its face tag; per feature mesh edge its B-rep edge.
struct SurfaceLocator {
    std::vector<int> face_tag, edge_tag;
    std::unordered_map<TriangleKey, int, TriangleKeyHash> triangle_tag;
    std::unordered_map<PairKey, int> segment_tag;
    std::uint64_t stride = 0;      // the vertex count, for edge_key
    explicit SurfaceLocator(const TetMesh& mesh);
};

// What a complex edge lies on: feature curves when most of its chain's mesh edges lie on them,
// else the boundary when most of its vertices do, else nothing. Per chain segment the B-rep edge
// or face tag under it: one hex edge may run along two CAD edges (an imprint ends on it).
struct EdgeSupport {
    enum Kind { inside, face, curve } kind = inside;
    Points chain;                  // the chain's vertex positions
    std::vector<int> tags;         // per segment (curve) or per vertex (face)
};

EdgeSupport edge_support(const TetMesh& mesh, const ComplexEdge& edge, const SurfaceLocator& at);
// Onto the B-rep edge or face under the chain segment (vertex) nearest p.
Eigen::Vector3d project_on_support(const Eigen::Vector3d& p, const EdgeSupport& support, const CadProjector& cad);
// A B-rep vertex stays; else onto the feature curve or the boundary face its cluster touches.
Eigen::Vector3d project_corner(const TetMesh& mesh, const ComplexCorner& corner, const SurfaceLocator& at,
                               const CadProjector& cad);

// Closest point on a complex face's triangles (a grid of their centroids: a face of a large part
// has 10^4-10^5 of them); on the boundary, then onto the B-rep face of the closest triangle.
class FaceProjector {
public:
    FaceProjector(const TetMesh& mesh, const ComplexFace& face, const SurfaceLocator& at);
    // `tag`: the closest triangle's B-rep face (0 between blocks); `normal`: its unit normal,
    // outward from the face's first block.
    Eigen::Vector3d project(const Eigen::Vector3d& p, const CadProjector& cad, int* tag = nullptr,
                            Eigen::Vector3d* normal = nullptr) const;

private:
    std::vector<std::array<Eigen::Vector3d, 3>> tris_;
    std::vector<int> tags_;
    bool boundary_;
    std::optional<PointGrid> centroids_;
    double cell_ = 0, reach_ = 0;  // grid spacing; largest centroid-to-corner distance
    int nearest_triangle(const Eigen::Vector3d& p, Eigen::Vector3d& q) const;
};

}  // namespace framefix
