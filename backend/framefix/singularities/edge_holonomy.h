#pragma once
// Per-edge holonomy, the alternative to the per-triangle holonomy of holonomy.h
// (docs/algorithms.md#per-edge-holonomy). Internal to singularities/, exposed for the tests.
//
// Each tet gets one frame: the projection of the mean of its four vertex coefficients. Tets that
// share a face share three of four vertices, so their frames are close and one direct matching
// transports a frame across the face. The holonomy of an interior mesh edge is the product of the
// matchings around its ring of tets; for 90 deg its world axis w and the edge direction d (the
// ring oriented right-handed about d) give the valence: 3 iff w.d > 0, as for triangles. Edges on
// the boundary have an open fan and no holonomy. Along a staircase of edges around a curve, the
// steps run across the curve and w.d is ~0 there, so edges on a curve are labelled again along
// it: w, turned to the chain's direction of travel, against the chain's local tangent
// (edge_chains.h, label_along_chains).
#include <vector>

#include <Eigen/Core>

#include "framefix/frame_field/frame_field.h"
#include "framefix/mesh/tet_mesh.h"
#include "framefix/mesh/tet_topology.h"

namespace framefix {

struct EdgeHolonomy {
    std::vector<int> valence;  // #Ed (topology edges): 0 regular or boundary, 3, 5, or -1 complex
    // #Ed x 3 world axis w of the holonomy for the ring right-handed about the edge's direction
    // (from its smaller vertex to its larger), 0 if regular.
    Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> axis;
};

// One rotation per tet (columns = axes), warm-started from its vertices' rotations.
std::vector<Eigen::Matrix3d> tet_rotations(const TetMesh& mesh, const FrameField& field,
                                           const std::vector<Eigen::Matrix3d>& vertex_rotation, int threads);

// The tets around interior edge e in ring order, or empty when e lies on the boundary.
std::vector<int> edge_ring(const TetMesh& mesh, const TetTopology& topo, int e);

EdgeHolonomy edge_holonomy(const TetMesh& mesh, const TetTopology& topo, const FrameField& field, int threads);

}  // namespace framefix
