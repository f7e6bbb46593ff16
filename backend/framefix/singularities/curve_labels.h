#pragma once
// Valence labels read along a curve (docs/algorithms.md#labels-along-the-curve). Internal to
// singularities/, exposed for the tests.
//
// An element's own label compares its holonomy axis w with its own normal: the loop normal of a
// triangle, the direction of an edge. Where that normal runs across the curve (a triangle the
// curve grazes, a step of a staircase of edges) w is nearly perpendicular to it and the sign is
// noise. Along a curve the element is crossed in a known direction of travel: its axis, turned to
// that direction, is compared with the curve's tangent over a few elements instead, 3 when they
// agree. Elements off every curve keep their own label.
#include <vector>

#include <Eigen/Core>

#include "framefix/singularities/chains.h"

namespace framefix {

using AxisRows = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

// Curves made of triangles (chains.h): face_axis and face_valence index topology faces.
void label_faces_along_curves(const TetMesh& mesh, const TetTopology& topo, const ChainGraph& graph,
                              const AxisRows& face_axis, std::vector<int>& face_valence);

// Curves made of edges (edge_chains.h): edge_axis (edge_holonomy.h) and edge_valence index topology edges.
void label_edges_along_curves(const TetMesh& mesh, const TetTopology& topo, const ChainGraph& graph,
                              const AxisRows& edge_axis, std::vector<int>& edge_valence);

}  // namespace framefix
