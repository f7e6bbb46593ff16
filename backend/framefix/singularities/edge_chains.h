#pragma once
// Singular mesh edges -> curves and nodes, the per-edge counterpart of chains.h
// (docs/algorithms.md#per-edge-holonomy). Internal to singularities/, exposed for the tests.
//
// - A vertex with exactly two singular edges (neither complex) links them, on the boundary too.
// - Interior vertices with >= 3 singular edges or a complex one are node vertices; node vertices
//   joined by a mesh edge are one junction.
// - A chain ends at a junction, at a boundary vertex (boundary end), or at an interior vertex
//   with one singular edge (dead end), which joins the nearest junction within attach_distance,
//   else the boundary when the vertex touches it, else the other dead ends close to it.
// - Boundary ends at one vertex, or at two vertices of one boundary triangle off the feature
//   curves, are one boundary node.
// - Junk and pass-through joins as for triangles (chains.h); ChainCurve::faces then holds edge
//   ids and the raw polyline runs through the edge midpoints.
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "framefix/singularities/chains.h"

namespace framefix {

// edge_valence: #Ed (topology edges) 0, 3, 5 or -1; edge_axis: #Ed x 3 holonomy axes. Boundary
// nodes get `axes_normal`: whether every curve-end edge's axis lies within 45 deg of the
// surface normal at its end vertex.
ChainGraph trace_edge_chains(const TetMesh& mesh, const TetTopology& topo, const std::vector<int>& edge_valence,
                             const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>& edge_axis,
                             const ChainOptions& options = {});

}  // namespace framefix
