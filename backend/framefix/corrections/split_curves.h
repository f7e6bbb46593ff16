#pragma once
// Feature curves that receive a snapped end point S (the paper's "split and interpolate";
// docs/algorithms.md#split-curves). On each curve the anchors are the S points (with their
// path frame) and the curve's two end vertices (with their existing Dirichlet frame); between
// consecutive anchors q = proj((1 - w) q_A + w q_B), w = normalised arc length. A closed curve
// whose CAD vertex is not a Dirichlet corner uses only its S anchors, cyclically.
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "framefix/frame_field/frame_field.h"
#include "framefix/frame_field/sh.h"
#include "framefix/mesh/features.h"
#include "framefix/mesh/tet_mesh.h"

namespace framefix {

struct FeatureChain {
    int tag = 0;                // B-rep edge id (mesh.edge_tags)
    std::vector<int> vertices;  // ordered along the curve; a closed curve repeats its first vertex at the end
    bool closed = false;
};

// One chain per feature-edge tag whose valence is > 0 (all tags when `features` is empty).
std::vector<FeatureChain> feature_chains(const TetMesh& mesh, const FeatureSet& features);

// New Dirichlet frames (vertex, unit SH9) on the chains holding an anchor or a collapsed point.
// `anchors` maps a snapped feature vertex to its path frame; `collapsed` holds feature vertices
// onto which a whole curve was snapped (no path, no frame of their own): their chain is
// re-interpolated between its other anchors, which is how the paper's box with an imprinted arc
// becomes "as if there were no imprinted curve". `original` gives the curves' existing frames.
std::vector<std::pair<int, SH9>> interpolate_split_curves(const Points& points, const std::vector<FeatureChain>& chains,
                                                          const Constraints& original,
                                                          const std::map<int, SH9>& anchors,
                                                          const std::set<int>& collapsed = {});

}  // namespace framefix
