#pragma once
// Where a sheet leaves a feature curve (docs/algorithms.md#feature-seeds): one seed per curve
// vertex, and the frame axes that continue the curve's faces into the solid. A feature of hex
// valence k has k - 1 such directions: 2 (imprinted) one, 3 (concave) two, 4 (slit) three.
// Used by the blocks (concave sheets) and by the feature-curve extrusion.
#include <vector>

#include <Eigen/Core>

#include "framefix/frame_field/frame_field.h"
#include "framefix/mesh/features.h"
#include "framefix/mesh/tet_mesh.h"

namespace framefix {

struct FeatureSeed {
    int vertex = -1;                                    // mesh vertex on the curve
    Eigen::Vector3d point = Eigen::Vector3d::Zero();    // its position, model units
    Eigen::Vector3d tangent = Eigen::Vector3d::Zero();  // unit tangent of the curve there
    // Unit directions into the solid, in the same order at every seed of a curve (one sheet
    // each); a seed whose faces are unknown (a corner) may have fewer.
    std::vector<Eigen::Vector3d> directions;
};

struct FeatureSeeds {
    int edge = 0;                    // B-rep edge (the mesh's edge tag)
    int valence = 0;                 // of the feature curve
    std::vector<FeatureSeed> seeds;  // in curve order, one per mesh vertex
};

// Seeds of the feature curves listed in `edges` (B-rep edge ids of valence 2, 3 or 4; others
// are skipped). `field` gives the frame axes at the curve's vertices.
std::vector<FeatureSeeds> feature_seeds(const TetMesh& mesh, const FeatureSet& features, const FrameField& field,
                                        const std::vector<int>& edges);

}  // namespace framefix
