// snap_three_five_curves end to end on the cube fixture with hand-made singularity graphs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "framefix/core/error.h"
#include "framefix/corrections/free_boundary.h"
#include "framefix/corrections/snapping.h"
#include "framefix/corrections/split_curves.h"
#include "framefix/frame_field/projection.h"
#include "backend/corrections/cube_frames.h"

namespace framefix {
namespace {

using test::curve_between;
using test::node_at;

// One 3-5 curve from near the edge y=0,z=0 to near the edge y=1,z=0, just above the face z=0.
SingularityGraph one_three_five_curve() {
    SingularityGraph g;
    g.nodes.push_back(node_at(0, {0.5, 0.02, 0.03}, true));
    g.nodes.push_back(node_at(1, {0.5, 0.98, 0.03}, true));
    g.curves.push_back(curve_between(0, 0, 1, CurveKind::ThreeFive));
    return g;
}

bool same_constraints(const Constraints& a, const Constraints& b) {
    return a.kind == b.kind && a.normal == b.normal && a.fixed == b.fixed;
}

double distance_to_paths(const Eigen::Vector3d& p, const std::vector<SnappedPath>& paths) {
    double d = std::numeric_limits<double>::infinity();
    for (const SnappedPath& path : paths)
        for (int k = 0; k + 1 < path.points.rows(); ++k)
            d = std::min(d, point_segment_distance(p, path.points.row(k), path.points.row(k + 1)));
    return d;
}

TEST(Snapping, GraphWithoutThreeFiveCurveLeavesConstraintsIdentical) {
    const test::Cube c = test::cube_tets(6);
    SingularityGraph g;
    g.nodes.push_back(node_at(0, {0.5, 0.02, 0.03}, true));
    g.nodes.push_back(node_at(1, {0.5, 0.98, 0.03}, true));
    g.curves.push_back(curve_between(0, 0, 1, CurveKind::Valence3));
    const SnapResult r = snap_three_five_curves(c.mesh, c.topo, c.features, c.constraints, c.field, g);
    EXPECT_TRUE(same_constraints(r.constraints, c.constraints));
    EXPECT_TRUE(r.paths.empty());
    EXPECT_EQ(r.snapped_curves, 0);
    EXPECT_EQ(r.freed_vertices, 0);
    EXPECT_EQ(r.three_five_curves, 0);
}

TEST(Snapping, ThreeFiveCurveBecomesADirichletPathWithFreedSurroundings) {
    const test::Cube c = test::cube_tets(8);
    const SnapResult r = snap_three_five_curves(c.mesh, c.topo, c.features, c.constraints, c.field, one_three_five_curve());
    EXPECT_EQ(r.three_five_curves, 1);
    EXPECT_EQ(r.snapped_curve_ids, std::vector<int>{0});
    ASSERT_EQ(r.paths.size(), 1u);
    const SnappedPath& p = r.paths[0];
    EXPECT_EQ(p.vertices.front(), c.vertex(4, 0, 0));
    EXPECT_EQ(p.vertices.back(), c.vertex(4, 8, 0));
    EXPECT_FALSE(p.crosses_features);
    for (int v : p.vertices) {
        EXPECT_EQ(r.constraints.kind[v], ConstraintKind::Fixed);
        EXPECT_EQ(r.vertex_role[v], SnapRole::Path);
    }
    // Path frames: one axis along the path (y), the others 45 deg from the face normal (z).
    for (int k = 0; k < p.frames.rows(); ++k) {
        const Eigen::Matrix3d R = project_frame(p.frames.row(k).transpose()).rotation;
        double along = 0, max_z = 0;
        for (int a = 0; a < 3; ++a) along = std::max(along, std::abs(R.col(a).y())), max_z = std::max(max_z, std::abs(R.col(a).z()));
        EXPECT_NEAR(along, 1.0, 1e-6);
        EXPECT_NEAR(max_z, std::sqrt(0.5), 1e-6);
    }
}

TEST(Snapping, FreedVerticesAreWithinTheRadiusAndNeverDirichlet) {
    const test::Cube c = test::cube_tets(8);
    SnapOptions options;
    const SnapResult r = snap_three_five_curves(c.mesh, c.topo, c.features, c.constraints, c.field,
                                                one_three_five_curve(), options);
    ASSERT_GT(r.freed_vertices, 0);
    int freed = 0;
    for (int v = 0; v < c.mesh.num_vertices(); ++v) {
        if (r.vertex_role[v] != SnapRole::Freed) continue;
        ++freed;
        EXPECT_EQ(c.constraints.kind[v], ConstraintKind::NormalAligned) << "vertex " << v;
        EXPECT_EQ(r.constraints.kind[v], ConstraintKind::Free);
        EXPECT_LE(distance_to_paths(c.point(v), r.paths), options.free_radius_hb * r.hb + 1e-12);
    }
    EXPECT_EQ(freed, r.freed_vertices);
    // Every tangency vertex within the radius was freed.
    for (int v = 0; v < c.mesh.num_vertices(); ++v)
        if (c.constraints.kind[v] == ConstraintKind::NormalAligned && r.vertex_role[v] != SnapRole::Path &&
            distance_to_paths(c.point(v), r.paths) < options.free_radius_hb * r.hb - 1e-9)
            EXPECT_EQ(r.constraints.kind[v], ConstraintKind::Free) << "vertex " << v;
    // Dirichlet vertices of the cube edges stay untouched unless they are path end points.
    for (int v = 0; v < c.mesh.num_vertices(); ++v) {
        if (c.constraints.kind[v] != ConstraintKind::Fixed || r.vertex_role[v] == SnapRole::Path) continue;
        EXPECT_EQ(r.constraints.kind[v], ConstraintKind::Fixed);
        EXPECT_EQ(r.constraints.fixed.row(v), c.constraints.fixed.row(v));
    }
}

TEST(Snapping, ZeroRadiusFreesNothing) {
    const test::Cube c = test::cube_tets(6);
    SnapOptions options;
    options.free_radius_hb = 0;
    const SnapResult r = snap_three_five_curves(c.mesh, c.topo, c.features, c.constraints, c.field,
                                                one_three_five_curve(), options);
    EXPECT_EQ(r.freed_vertices, 0);
}

TEST(Snapping, InterpolationReanchorsTheSplitFeatureCurves) {
    const test::Cube c = test::cube_tets(8);
    SnapOptions options;
    options.interpolate_split_curves = true;
    const SnapResult r = snap_three_five_curves(c.mesh, c.topo, c.features, c.constraints, c.field,
                                                one_three_five_curve(), options);
    // The two cube edges holding the path ends (x-edges at y=0 and y=1 on z=0) are re-interpolated
    // between their corners and S: 7 inner vertices each, minus S.
    int split = 0;
    for (SnapRole role : r.vertex_role) split += role == SnapRole::SplitCurve;
    EXPECT_EQ(split, 2 * 6);
    // Corners keep their frame (end anchors).
    EXPECT_EQ(r.constraints.fixed.row(c.vertex(0, 0, 0)), c.constraints.fixed.row(c.vertex(0, 0, 0)));
}

TEST(Snapping, SplitCurveInterpolationHitsItsAnchors) {
    const test::Cube c = test::cube_tets(4);
    const auto chains = feature_chains(c.mesh, c.features);
    ASSERT_EQ(chains.size(), 12u);
    for (const FeatureChain& ch : chains) EXPECT_EQ(ch.vertices.size(), 5u);
    Eigen::Matrix3d R = Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitX()).toRotationMatrix();
    const SH9 anchor = frame_from_rotation(R);
    const int s = c.vertex(2, 0, 0);
    const auto frames = interpolate_split_curves(c.mesh.points, chains, c.constraints, {{s, anchor}});
    ASSERT_FALSE(frames.empty());
    for (const auto& [v, q] : frames) {
        EXPECT_NEAR(q.norm(), 1.0, 1e-9);
        if (v == s) EXPECT_LT((q - anchor).norm(), 1e-9);
        if (v == c.vertex(0, 0, 0) || v == c.vertex(4, 0, 0))
            EXPECT_LT((q - c.constraints.fixed.row(v).transpose()).norm(), 1e-9);
    }
}

TEST(Snapping, RejectsConstraintsOfAnotherMesh) {
    const test::Cube c = test::cube_tets(3);
    const test::Cube other = test::cube_tets(4);
    EXPECT_THROW(snap_three_five_curves(c.mesh, c.topo, c.features, other.constraints, c.field, one_three_five_curve()), Error);
}

TEST(Snapping, CurveCollapsedOntoAFeatureVertexReinterpolatesItsCurve) {
    const test::Cube c = test::cube_tets(8);
    // Both ends of a short 3-5 curve next to the edge y=0, z=0: one target, no path.
    SingularityGraph g;
    g.nodes.push_back(node_at(0, {0.49, 0.03, 0.02}, true));
    g.nodes.push_back(node_at(1, {0.51, 0.02, 0.03}, true));
    g.curves.push_back(curve_between(0, 0, 1, CurveKind::ThreeFive, 4));
    const SnapResult r = snap_three_five_curves(c.mesh, c.topo, c.features, c.constraints, c.field, g);
    EXPECT_EQ(r.snapped_curves, 1);
    EXPECT_TRUE(r.paths.empty());
    int split = 0;
    for (int v = 0; v < c.mesh.num_vertices(); ++v) {
        if (r.vertex_role[v] != SnapRole::SplitCurve) continue;
        ++split;
        EXPECT_NEAR(c.point(v).y(), 0.0, 1e-12);
        EXPECT_NEAR(c.point(v).z(), 0.0, 1e-12);
        // Between two identity corners the interpolated frame is the identity.
        EXPECT_LT((r.constraints.fixed.row(v) - c.constraints.fixed.row(v)).norm(), 1e-9);
    }
    EXPECT_EQ(split, 7);  // the inner vertices of that cube edge
}

TEST(Snapping, InconsistentCornerFrameIsNotUsedAsAnAnchor) {
    test::Cube c = test::cube_tets(4);
    // Corner (0,0,0) carries a frame 45 deg off its curves' frames (a bad corner rule).
    const int corner = c.vertex(0, 0, 0);
    const Eigen::Matrix3d R = Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitX()).toRotationMatrix();
    c.constraints.fixed.row(corner) = frame_from_rotation(R).transpose();
    const auto frames = interpolate_split_curves(c.mesh.points, feature_chains(c.mesh, c.features), c.constraints, {},
                                                 {c.vertex(2, 0, 0)});
    ASSERT_FALSE(frames.empty());
    const SH9 identity = frame_from_rotation(Eigen::Matrix3d::Identity());
    for (const auto& [v, q] : frames) EXPECT_LT((q - identity).norm(), 1e-9) << "vertex " << v;
}

}  // namespace
}  // namespace framefix
