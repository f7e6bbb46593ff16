// Labels read along a curve (curve_labels.h) on the synthetic fields of fixtures.h: the oracle
// is the field's construction.
#include <gtest/gtest.h>

#include "backend/singularities/fixtures.h"
#include "framefix/singularities/singularity_graph.h"

namespace framefix {
namespace {

using testing::LineField;

SingularityOptions own_labels() {
    SingularityOptions o;
    o.labels_along_curves = false;
    o.surface_end_labels = false;
    return o;
}

int wrong_labels(const SingularityGraph& g, int expected) {
    int wrong = 0;
    for (const SingularCurve& c : g.curves)
        for (int v : c.valences) wrong += v != expected;
    return wrong;
}

TEST(CurveLabels, ReadingAlongAnObliqueLineKeepsItsValence) {
    // A line far from the grid axes: the tangent and the triangles' own normals both give the
    // construction's valence (the gain on solved fields is in tests/python/test_labels.py).
    const testing::Fixture fx = testing::cube_tets(8);
    const TetTopology topo = build_topology(fx.mesh);
    const Eigen::Vector3d d = Eigen::Vector3d(1, 0.9, 0.35).normalized();
    for (double index : {0.25, -0.25}) {
        const FrameField f = testing::field_of(fx.mesh, LineField{Eigen::Vector3d(0.5, 0.5, 0.5), d, index});
        const int expected = index > 0 ? 3 : 5;
        const SingularityGraph own = extract_singularities(fx.mesh, topo, f, own_labels());
        const SingularityGraph along = extract_singularities(fx.mesh, topo, f);
        ASSERT_EQ(along.summary.curves, 1);
        EXPECT_EQ(along.curves[0].kind, index > 0 ? CurveKind::Valence3 : CurveKind::Valence5);
        EXPECT_EQ(wrong_labels(own, expected), 0) << "index " << index;
        EXPECT_EQ(wrong_labels(along, expected), 0) << "index " << index;
    }
}

}  // namespace
}  // namespace framefix
