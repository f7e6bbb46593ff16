// Junction ends of sheet sources: which seed stands for the end at the node, the tangent leaving
// it, and which curves run straight on through the node (the zip modes' test).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "framefix/blocks/sheet_sources.h"

namespace framefix {
namespace {

constexpr int kNode = 7;

// A source of seeds every unit along `dir` from `from`; `directions` per seed (count only).
SheetSource line_source(const Eigen::Vector3d& from, const Eigen::Vector3d& dir, const std::vector<int>& directions) {
    SheetSource s;
    for (size_t i = 0; i < directions.size(); ++i) {
        SheetSeed seed;
        seed.point = from + double(i) * dir.normalized();
        seed.tangent = dir.normalized();
        seed.directions.assign(size_t(directions[i]), Eigen::Vector3d::UnitZ());
        s.seeds.push_back(seed);
    }
    return s;
}

Eigen::Vector3d at_deg(double deg) {  // unit vector in the xy plane, deg from +x
    return {std::cos(deg * M_PI / 180), std::sin(deg * M_PI / 180), 0};
}

TEST(JunctionEnd, TakesTheFullestOfTheThreeSeedsNearestTheNodeAndTheTangentLeavingIt) {
    SheetSource a = line_source(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), {2, 4, 3, 4, 4});
    a.junction[0] = kNode;
    const JunctionEnd e0 = junction_end(a, 0);
    EXPECT_EQ(e0.seed, 1);  // the seed on the node lost two directions; the next has all four
    EXPECT_NEAR(e0.tangent.dot(Eigen::Vector3d::UnitX()), 1.0, 1e-12);
    const JunctionEnd e1 = junction_end(a, 1);  // the far end: seeds 4, 3, 2
    EXPECT_EQ(e1.seed, 4);
    EXPECT_NEAR(e1.tangent.dot(-Eigen::Vector3d::UnitX()), 1.0, 1e-12);
    EXPECT_EQ(junction_end(line_source(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), {4}), 0).seed, -1);
}

TEST(StraightThrough, TwoHalvesOfOneCurveAtTheirNodeButNotACurveLeavingAcross) {
    std::vector<SheetSource> s;
    s.push_back(line_source(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), {4, 4, 4}));  // leaves along +x
    s.back().junction[0] = kNode;
    // Ends at the node, arriving from 160 deg: leaves it along 160 deg, 20 deg off straight on.
    s.push_back(line_source(3 * at_deg(160), -at_deg(160), {4, 4, 4, 4}));
    s.back().junction[1] = kNode;
    s.push_back(line_source(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), {4, 4, 4}));  // leaves upwards
    s.back().junction[0] = kNode;
    EXPECT_TRUE(straight_through(s, 0, 0, 1, 1));
    EXPECT_TRUE(straight_through(s, 1, 1, 0, 0));
    EXPECT_FALSE(straight_through(s, 0, 0, 2, 0));  // at 90 deg: another sheet's curve
    EXPECT_FALSE(straight_through(s, 0, 0, 0, 0));  // not with itself
    EXPECT_FALSE(straight_through(s, 0, 1, 1, 1));  // the far end is on no node
    EXPECT_TRUE(has_straight_junction(s));
    s.erase(s.begin() + 1);
    EXPECT_FALSE(has_straight_junction(s));
}

TEST(StraightThrough, NeedsTheSameNodeAndTangentsWithin45Degrees) {
    std::vector<SheetSource> s;
    s.push_back(line_source(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), {4, 4, 4}));
    s.back().junction[0] = kNode;
    s.push_back(line_source(Eigen::Vector3d::Zero(), at_deg(130), {4, 4, 4}));  // 50 deg off straight on
    s.back().junction[0] = kNode;
    EXPECT_FALSE(straight_through(s, 0, 0, 1, 0));
    s[1] = line_source(Eigen::Vector3d::Zero(), at_deg(140), {4, 4, 4});  // 40 deg off
    s[1].junction[0] = kNode;
    EXPECT_TRUE(straight_through(s, 0, 0, 1, 0));
    s[1].junction[0] = kNode + 1;  // another node at the same place
    EXPECT_FALSE(straight_through(s, 0, 0, 1, 0));
}

}  // namespace
}  // namespace framefix
