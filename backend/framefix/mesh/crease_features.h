#pragma once
// Feature curves of an imported tet mesh (no B-rep): boundary edges whose dihedral angle is
// sharp. Outward normals of the two boundary triangles at an edge more than `angle_deg` apart
// make a crease. Triangles joined through non-crease edges form "faces" (face_tags); crease
// edges are chained into curves (edge_tags) between vertices where the crease count is not 2 or
// the pair of adjacent faces changes. Each curve's dihedral angle inside the solid, theta, is
// 180 - alpha at a convex and 180 + alpha at a concave edge (alpha = angle between the normals),
// averaged over its edges; valence = round(theta / 90 deg) clamped to 1..4.
// Imprinted curves (180 deg) are invisible here: they have no crease.
#include "framefix/mesh/features.h"
#include "framefix/mesh/tet_mesh.h"

namespace framefix {

struct CreaseOptions {
    double angle_deg = 30;  // crease threshold between outward normals, degrees; typically 20..40
                            // (30 is also the B-rep threshold: docs/algorithms.md#feature-classification)
};

struct CreaseFeatures {
    TetMesh mesh;         // the input with face_tags, feature_edges, edge_tags, corner_vertices replaced:
                          //   face_tags 1..#faces, edge_tags 1..#curves, corner_vertices = vertices
                          //   where >= 3 crease edges meet
    FeatureSet features;  // one entry per curve, features.edges[i].edge == i + 1
};

// Deterministic: numbering follows the smallest triangle / edge index of each face / curve.
CreaseFeatures detect_crease_features(TetMesh mesh, const CreaseOptions& options = {});

}  // namespace framefix
