#pragma once
// Flat corners along concave feature curves (docs/algorithms.md#flat-corners). Where a valence-5
// curve lies on a concave feature curve, for example a fillet's valence-5 curve mapped back onto
// the edge the fillet replaced, two hexes meet along the edge at 135 deg instead of three at
// 90 deg. The edge's Dirichlet frames there turn by 45 deg about its tangent, which puts one axis
// on the bisector of the two faces, and the field is solved again on the same mesh.
#include <vector>

#include "framefix/frame_field/frame_field.h"
#include "framefix/mesh/features.h"
#include "framefix/mesh/tet_mesh.h"

namespace framefix {

struct EdgeRun {   // a valence-5 curve's stretch along one feature curve, in curve order
    int edge = 0;  // B-rep edge id (mesh.edge_tags)
    Points points; // >= 2 points on the edge, model units
};

struct FlatCorners {
    Constraints constraints;  // the input's, with the covered edge vertices turned
    int turned_vertices = 0;
};

// Feature-curve vertices of each run's edge within half an edge spacing of the run get their
// frame turned; the edge's end vertices (CAD vertices, corner frames) keep theirs.
FlatCorners flat_corner_constraints(const TetMesh& mesh, const FeatureSet& features, const Constraints& constraints,
                                    const std::vector<EdgeRun>& runs);

}  // namespace framefix
