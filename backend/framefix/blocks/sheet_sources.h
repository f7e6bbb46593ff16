#pragma once
// Seeds and start directions of the separatrix sheets (docs/algorithms.md#sheet-sources). Internal to blocks.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "framefix/blocks/blocks.h"
#include "framefix/streamlines/feature_seeds.h"
#include "framefix/streamlines/tet_locator.h"

namespace framefix {

struct SheetSeed {
    Eigen::Vector3d point = Eigen::Vector3d::Zero();    // on the source curve, model units
    Eigen::Vector3d tangent = Eigen::Vector3d::Zero();  // unit tangent of the source curve
    std::vector<Eigen::Vector3d> directions;            // unit start directions, one per sheet
    bool continue_jumps = true;  // a direction jump at this seed starts a cross extension
};

struct SheetSource {
    enum Kind { Singular, Concave, Imprinted, Snapped, Ring } kind = Singular;
    // "singular:<curve id>" | "glued:<index>" | "concave:<B-rep edge>" | "imprinted:<B-rep edge>" | "snapped:<path>" | "ring:<block>"
    std::string name;
    std::vector<SheetSeed> seeds;      // in curve order, about one per h
    bool boundary_end[2] = {false, false};  // source end lies on the boundary: extend the sheet past it
    // Singular curves: the interior node at each end where at least three curves meet, else -1.
    // There a sheet's continuation past the end may be another curve's sheet (sheets.cpp).
    int junction[2] = {-1, -1};
    // A closed curve (a circle, a loop): its first and last seeds are neighbours. The sheet is
    // zipped across them and has no end to extend or continue.
    bool closed = false;
};

// At end f of a source ending at a junction node: the seed whose directions stand for the end
// (the seed on the node often lacks directions, so the fullest of the three nearest it; -1 for a
// source of fewer than 2 seeds) and the unit tangent leaving the node, read over two seeds (a
// curve can bend within 1 h of its node).
struct JunctionEnd {
    int seed = -1;
    Eigen::Vector3d tangent = Eigen::Vector3d::Zero();
};
JunctionEnd junction_end(const SheetSource& source, int f);

// 45 deg: a curve's tangent picks which sheet at a junction node it continues.
constexpr double kJunctionAlongCos = 0.7;

// End f of source sj runs straight on from end e of source si through their common junction node
// (the two halves of the filleted notch's valence-5 curve): tangents leaving the node opposite
// within 45 deg.
bool straight_through(const std::vector<SheetSource>& sources, int si, int e, int sj, int f);

// Some junction node has a curve running straight on through it.
bool has_straight_junction(const std::vector<SheetSource>& sources);

// A singular curve from the boundary to the boundary shorter than kWispLength_h h lies within one
// hex layer of the surface: no hex mesh of this size can follow it, yet its sheets would cut the
// whole part (the groove after snapping keeps a 0.65 h valence-5 stub where the inner snapped
// path meets the floor; its five sheets ran through the whole box). Ids of such curves, ascending.
constexpr double kWispLength_h = 1.0;
std::vector<int> boundary_wisps(const SingularityGraph& graph, double h);

// Singular curves (not kind Other, >= 3 triangles, not in `skip`, ascending ids): seeds every
// seed_spacing h on the polyline, directions = zeros of the radial deviation of the closest frame
// axis on a circle of radius seed_radius h around the curve (valence k gives k zeros; seeds with
// fewer keep what they find).
std::vector<SheetSource> singular_sources(const TetMesh& mesh, const FrameField& field, const SingularityGraph& graph,
                                          const TetLocator& locator, double h, const BlockOptions& options,
                                          const std::vector<int>& skip = {});

// The curves glued to ambiguous feature curves (SingularityGraph::absorbed) as singular sources
// with boundary ends, for the blocks that try them (build_blocks): on the anti-pentapyramid the
// hex layers need them, on the chamfered box they must not be there. Named "glued:<index>".
std::vector<SheetSource> glued_sources(const TetMesh& mesh, const FrameField& field, const SingularityGraph& graph,
                                       const TetLocator& locator, double h, const BlockOptions& options);

// Imprinted feature curves (valence 2) that the field follows: at the curve's inner vertices the
// frame axis closest to the tangent is within kFollowDeg of it on average. A field that ignores an
// imprint (box with an arc after snapping: "as if there were no imprinted curve") gives the blocks
// no reason to follow it. Ambiguous edges (a chamfer's 135 degrees) are not imprints: they are
// left to the block faces (build_blocks). B-rep edge ids, ascending.
std::vector<int> followed_imprints(const TetMesh& mesh, const FeatureSet& features, const FrameField& field);

// The chain of a closed feature curve (a circle) ends next to where it starts: its two end seeds
// are no further apart than 1.5 of its longest step.
bool closed_chain(const std::vector<FeatureSeed>& seeds);

// Per snapped path: does it lie on a convex surface, bending away from the solid by more than
// kConvexPathBend per h across the path? Such a path emits no sheet of its own: the bulge (the
// groove's island, a dome, a boss) is one block whose face the path splits, and the hex layers
// turn at the corner line of the curtain below it instead (curtain_corners.h).
std::vector<char> convex_paths(const TetMesh& mesh, const FeatureSet& features, const std::vector<SnappedPath>& paths,
                               double h);

// `curves`: the seeds (feature_seeds) of the concave feature curves (valence 3: one seed per curve
// vertex, directions = the frame axes closest to -n1, -n2, the inward continuations of the two
// faces) and of the followed imprinted curves (one direction, the axis closest to -n). Snapped paths: one seed per path vertex,
// directions = the two axes with a.n < -0.3 (the 45 deg path frame's inward axes); paths flagged
// in `convex` emit none.
std::vector<SheetSource> feature_sources(const TetMesh& mesh, const FeatureSet& features, const FrameField& field,
                                         const std::vector<FeatureSeeds>& curves, const std::vector<SnappedPath>& paths,
                                         const std::vector<char>& convex);

}  // namespace framefix
