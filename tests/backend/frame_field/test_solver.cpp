#include <cmath>

#include <gtest/gtest.h>

#include "backend/frame_field/twisted_cube.h"
#include "backend/mesh/cube_fixture.h"
#include "framefix/core/error.h"
#include "framefix/frame_field/frame_field.h"
#include "framefix/frame_field/projection.h"

namespace framefix {
namespace {

struct Solved {
    testing::Fixture fx;
    TetTopology topo;
    Constraints cons;
    FrameField field;
};

Solved solve(testing::Fixture fx, FieldOptions o = {}) {
    Solved s{std::move(fx), {}, {}, {}};
    s.topo = build_topology(s.fx.mesh);
    s.cons = boundary_constraints(s.fx.mesh, s.fx.features);
    s.field = solve_frame_field(s.fx.mesh, s.topo, s.cons, o);
    return s;
}

double max_frame_error(const FrameField& f, const SH9& expected) {
    double err = 0;
    for (int v = 0; v < f.coefficients.rows(); ++v)
        err = std::max(err, (f.coefficients.row(v).transpose() - expected).norm());
    return err;
}

TEST(Constraints, CubeKinds) {
    const testing::Fixture fx = testing::cube_tets(4);
    const Constraints c = boundary_constraints(fx.mesh, fx.features);
    int fixed = 0, aligned = 0, free = 0;
    for (ConstraintKind k : c.kind) {
        fixed += k == ConstraintKind::Fixed;
        aligned += k == ConstraintKind::NormalAligned;
        free += k == ConstraintKind::Free;
    }
    EXPECT_EQ(fixed, 8 + 12 * 3);      // corners (three faces) + edge vertices
    EXPECT_EQ(aligned, 6 * 3 * 3);     // face-interior vertices
    EXPECT_EQ(free, 3 * 3 * 3);        // interior
    for (int v = 0; v < int(c.kind.size()); ++v)
        if (c.kind[v] == ConstraintKind::Fixed)
            EXPECT_LT((c.fixed.row(v).transpose() - reference_frame()).norm(), 1e-12);
}

TEST(Solver, CubeFieldIsConstant) {
    const Solved s = solve(testing::cube_tets(4));
    EXPECT_LT(max_frame_error(s.field, reference_frame()), 1e-6);
    EXPECT_LT(s.field.energy, 1e-10);
    EXPECT_EQ(s.field.axes.rows(), s.fx.mesh.num_vertices());
}

TEST(Solver, RotatedCubeGivesTheRotatedFrame) {
    const Eigen::Matrix3d Q = (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, -2, 0.5).normalized()) *
                               Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitZ())).toRotationMatrix();
    const Solved s = solve(testing::rotated(testing::cube_tets(4), Q));
    EXPECT_LT(max_frame_error(s.field, frame_from_rotation(Q)), 1e-6);
    for (int v = 0; v < s.fx.mesh.num_vertices(); ++v) {
        Eigen::Matrix3d R;
        for (int a = 0; a < 3; ++a) R.col(a) = s.field.axes.block<1, 3>(v, 3 * a).transpose();
        EXPECT_LT((match_frame(Q, R) - Q).norm(), 1e-5);
    }
}

TEST(Solver, ConstraintsHoldExactlyAfterTheSolve) {
    const testing::Fixture fx = twisted_cube();
    const TetTopology topo = build_topology(fx.mesh);
    const Constraints c = twisted_constraints(fx.mesh);
    FieldOptions o;
    o.relaxed_final_step = true;  // the relaxed field must satisfy them too
    const FrameField f = solve_frame_field(fx.mesh, topo, c, o);
    EXPECT_GT(f.energy, 1e-3);  // really twisted
    for (int v = 0; v < fx.mesh.num_vertices(); ++v) {
        const SH9 q = f.coefficients.row(v).transpose();
        if (c.kind[v] == ConstraintKind::Fixed) {
            EXPECT_LT((q - c.fixed.row(v).transpose()).norm(), 1e-14);
        } else if (c.kind[v] == ConstraintKind::NormalAligned) {
            const NormalAligned fam = normal_aligned(c.normal.row(v).transpose());
            EXPECT_LT((q - fam.c - fam.P * (fam.P.transpose() * q)).norm(), 1e-12);  // q in c + range(P)
            const double along = f.axes.block<1, 3>(v, 6).dot(c.normal.row(v));
            EXPECT_NEAR(along, 1.0, 1e-12);  // axis 3 = n
        }
    }
}

// A singular frame (the extrusions' forced curves) is the axisymmetric element about its axis:
// accepted although it is no frame, kept exactly, and its axes have the imposed one.
TEST(Solver, SingularFramesAreKeptWithTheirAxis) {
    const testing::Fixture fx = testing::cube_tets(6);
    const TetTopology topo = build_topology(fx.mesh);
    Constraints c = boundary_constraints(fx.mesh, fx.features);
    const Eigen::Vector3d axis = Eigen::Vector3d(0, 0, 1);
    std::vector<int> line;
    for (int k = 2; k <= 4; ++k) line.push_back(testing::cube_vertex(6, 3, 3, k));
    for (int v : line) set_singular(c, v, axis);
    const FrameField f = solve_frame_field(fx.mesh, topo, c);
    const SH9 zonal = normal_aligned(axis).c;
    EXPECT_NEAR(zonal.norm(), std::sqrt(7.0 / 12.0), 1e-12);
    for (int v : line) {
        EXPECT_LT((f.coefficients.row(v).transpose() - zonal).norm(), 1e-14);
        EXPECT_NEAR(std::abs(f.axes.block<1, 3>(v, 6).dot(axis.transpose())), 1.0, 1e-12);
    }
}

TEST(Solver, DeterministicForTheSameInputAndThreads) {
    const testing::Fixture fx = twisted_cube();
    const TetTopology topo = build_topology(fx.mesh);
    const Constraints c = twisted_constraints(fx.mesh);
    FieldOptions o;
    o.threads = 2;
    const FrameField a = solve_frame_field(fx.mesh, topo, c, o);
    const FrameField b = solve_frame_field(fx.mesh, topo, c, o);
    EXPECT_TRUE(a.coefficients == b.coefficients);  // bit for bit
    EXPECT_EQ(a.iterations, b.iterations);
    // Fixed-block reductions: the thread count does not change the result either.
    o.threads = 1;
    const FrameField d = solve_frame_field(fx.mesh, topo, c, o);
    EXPECT_TRUE(a.coefficients == d.coefficients);
}

// MBO alternates an energy-decreasing diffusion with a projection that may raise the energy,
// so the energy is NOT monotone along the iterations (docs/algorithms.md#mbo-smoothing) and we do not test
// that. What holds: MBO starts from the projected linear init, its later small-tau steps only
// smooth at the mesh scale, and on a well-posed problem the final field has a lower energy than
// that starting point.
TEST(Solver, FinalEnergyIsBelowTheProjectedLinearInit) {
    const testing::Fixture fx = twisted_cube();
    const FrameField f = solve_frame_field(fx.mesh, build_topology(fx.mesh), twisted_constraints(fx.mesh));
    EXPECT_LE(f.energy, f.initial_energy);
    EXPECT_EQ(int(f.energy_history.size()), f.iterations);
    EXPECT_TRUE(f.converged);
}

// Extrapolation at the floor (off by default, docs/algorithms.md): with at least one jump taken,
// the same field with 1 and 2 threads, the constraints still exact, and an energy below the
// projected linear init.
TEST(Solver, ExtrapolationKeepsTheSolveDeterministicAndConstrained) {
    const testing::Fixture fx = twisted_cube();
    const TetTopology topo = build_topology(fx.mesh);
    const Constraints c = twisted_constraints(fx.mesh);
    FieldOptions o;
    o.extrapolate = true;
    o.threads = 2;
    const FrameField a = solve_frame_field(fx.mesh, topo, c, o);
    o.threads = 1;
    const FrameField b = solve_frame_field(fx.mesh, topo, c, o);
    EXPECT_TRUE(a.coefficients == b.coefficients);
    EXPECT_EQ(a.extrapolations, b.extrapolations);
    EXPECT_GE(a.extrapolations, 1);  // the twisted cube drifts at its floor: a jump is exercised
    EXPECT_LE(a.energy, a.initial_energy);
    for (int v = 0; v < fx.mesh.num_vertices(); ++v)
        if (c.kind[v] == ConstraintKind::Fixed)
            EXPECT_LT((a.coefficients.row(v) - c.fixed.row(v)).norm(), 1e-12);
    EXPECT_EQ(solve_frame_field(fx.mesh, topo, c).extrapolations, 0);  // off by default
}

// A fine mesh reaches the tau floor later; from large_mesh_vertices on, the cap leaves the floor
// floor_iterations iterations (docs/algorithms.md#large-meshes); below, max_iterations holds.
TEST(Solver, LargeMeshesLeaveTheFloorItsIterations) {
    const testing::Fixture fx = twisted_cube();
    const TetTopology topo = build_topology(fx.mesh);
    const Constraints c = twisted_constraints(fx.mesh);
    FieldOptions o;
    o.tolerance = 0;  // never converges: the cap decides
    o.floor_iterations = 70;
    const FrameField small = solve_frame_field(fx.mesh, topo, c, o);
    EXPECT_EQ(small.iteration_cap, 60);
    EXPECT_EQ(small.iterations, 60);
    o.large_mesh_vertices = 1;
    const FrameField large = solve_frame_field(fx.mesh, topo, c, o);
    EXPECT_GT(large.floor_iteration, 1);
    EXPECT_EQ(large.floor_iteration, small.floor_iteration);
    EXPECT_EQ(large.iteration_cap, large.floor_iteration - 1 + 70);
    EXPECT_EQ(large.iterations, large.iteration_cap);
}

TEST(Solver, DirectSolversAgreeWithCg) {
    const testing::Fixture fx = twisted_cube();
    const TetTopology topo = build_topology(fx.mesh);
    const Constraints c = twisted_constraints(fx.mesh);
    FieldOptions o;
    o.max_iterations = 3;
    o.cg_tolerance = 1e-10;
    const FrameField cg = solve_frame_field(fx.mesh, topo, c, o);
    for (SparseSolver kind : {SparseSolver::SimplicialLDLT, SparseSolver::Cholmod}) {
        o.solver = kind;
        const FrameField d = solve_frame_field(fx.mesh, topo, c, o);
        EXPECT_LT((d.coefficients - cg.coefficients).cwiseAbs().maxCoeff(), 1e-6) << d.solver;
    }
}

// The solver runs on a reverse Cuthill-McKee numbering (reorder.h) and maps every output back.
TEST(Solver, RenumberingDoesNotChangeTheField) {
    const testing::Fixture fx = twisted_cube();
    const TetTopology topo = build_topology(fx.mesh);
    const Constraints c = twisted_constraints(fx.mesh);
    FieldOptions o;
    o.max_iterations = 3;
    o.cg_tolerance = 1e-10;
    o.relaxed_final_step = true;
    const FrameField a = solve_frame_field(fx.mesh, topo, c, o);
    o.reorder = false;
    const FrameField b = solve_frame_field(fx.mesh, topo, c, o);
    EXPECT_LT((a.coefficients - b.coefficients).cwiseAbs().maxCoeff(), 1e-7);
    // (axes are not compared: the 24 rotations of a frame are equivalent, either may come out)
    EXPECT_LT((a.relaxed_norm - b.relaxed_norm).cwiseAbs().maxCoeff(), 1e-7);
    EXPECT_LT((a.distance - b.distance).cwiseAbs().maxCoeff(), 1e-6);
    EXPECT_NEAR(a.energy, b.energy, 1e-8 * b.energy);
}

TEST(Solver, BadInputIsAFieldError) {
    const testing::Fixture fx = testing::cube_tets(2);
    const TetTopology topo = build_topology(fx.mesh);
    Constraints c = boundary_constraints(fx.mesh, fx.features);
    c.kind.pop_back();
    EXPECT_THROW(solve_frame_field(fx.mesh, topo, c), Error);
    Constraints none = boundary_constraints(fx.mesh, fx.features);
    std::fill(none.kind.begin(), none.kind.end(), ConstraintKind::Free);
    EXPECT_THROW(solve_frame_field(fx.mesh, topo, none), Error);
}

}  // namespace
}  // namespace framefix
