// merge_small_pieces: a block's label split into face-connected pieces, the few tets cut off a
// block merged into a neighbour, a big piece kept as a block of its own.
#include <gtest/gtest.h>

#include <set>

#include "backend/corrections/cube_frames.h"
#include "framefix/blocks/partition.h"

namespace framefix {
namespace {

Eigen::Vector3d centroid(const TetMesh& mesh, int t) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k) c += mesh.points.row(mesh.tets(t, k)).transpose() / 4;
    return c;
}

// Two halves of the cube fixture, x below and above the middle, as labels 0 and 1.
Eigen::VectorXi halves(const test::Cube& c, double mid) {
    Eigen::VectorXi lab(c.mesh.num_tets());
    for (int t = 0; t < c.mesh.num_tets(); ++t) lab[t] = centroid(c.mesh, t).x() < mid ? 0 : 1;
    return lab;
}

int count_labels(const Eigen::VectorXi& lab) { return int(std::set<int>(lab.data(), lab.data() + lab.size()).size()); }

TEST(MergeSmallPieces, AFewTetsCutOffABlockJoinTheBlockAroundThem) {
    const test::Cube c = test::cube_tets(8);
    const Eigen::Vector3d lo = c.mesh.points.colwise().minCoeff(), hi = c.mesh.points.colwise().maxCoeff();
    const double mid = (lo.x() + hi.x()) / 2;
    Eigen::VectorXi lab = halves(c, mid);
    // A tet deep inside half 0 labelled 1: the same label as half 1, but not face-connected to it.
    int island = -1;
    for (int t = 0; t < c.mesh.num_tets() && island < 0; ++t)
        if ((centroid(c.mesh, t) - Eigen::Vector3d(lo.x() + 0.25 * (hi.x() - lo.x()), (lo.y() + hi.y()) / 2, (lo.z() + hi.z()) / 2)).norm() <
            0.1 * (hi.x() - lo.x()))
            island = t;
    ASSERT_GE(island, 0);
    lab[island] = 1;
    EXPECT_EQ(merge_small_pieces(c.topo, lab, 10), 1);
    EXPECT_EQ(count_labels(lab), 2);
    const Eigen::VectorXi expected = halves(c, mid);
    for (int t = 0; t < c.mesh.num_tets(); ++t) ASSERT_EQ(lab[t] == lab[island], expected[t] == 0) << "tet " << t;
}

TEST(MergeSmallPieces, ABigPieceOfTheSameLabelBecomesABlockOfItsOwn) {
    const test::Cube c = test::cube_tets(6);
    const Eigen::Vector3d lo = c.mesh.points.colwise().minCoeff(), hi = c.mesh.points.colwise().maxCoeff();
    const double third = (hi.x() - lo.x()) / 3;
    Eigen::VectorXi lab(c.mesh.num_tets());
    for (int t = 0; t < c.mesh.num_tets(); ++t) {
        const double x = centroid(c.mesh, t).x();
        lab[t] = x < lo.x() + third || x > hi.x() - third ? 0 : 1;  // label 0 on both sides of label 1
    }
    EXPECT_EQ(merge_small_pieces(c.topo, lab, 10), 0);
    EXPECT_EQ(count_labels(lab), 3);
}

}  // namespace
}  // namespace framefix
