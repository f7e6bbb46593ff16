#pragma once
// Streamlines of a frame field (paper Algorithm 1; docs/algorithms.md#rk4-tracing):
// RK4 in the "closest direction" field, i.e. at a point p and a current direction v, the
// barycentric average of the per-vertex frame axes closest to v (no projection per stage).
// A streamline follows one axis family through the field; it stops when it leaves the solid, comes
// near a singular curve, turns sharply (a singularity the caller did not list), grows longer than
// the limit-cycle bound, or runs out of steps. This module traces; it does not build surfaces.
#include <vector>

#include <Eigen/Core>

#include "framefix/frame_field/frame_field.h"
#include "framefix/mesh/tet_mesh.h"
#include "framefix/mesh/tet_topology.h"
#include "framefix/streamlines/tet_locator.h"

namespace framefix {

enum class StopReason : int {
    LeftSolid = 0,        // stepped out through the boundary; the last point is clipped onto it
    ReachedSingularity,   // came within stop_distance of a point of TraceOptions::singular_points
    SharpTurn,            // consecutive directions differ by more than max_turn_deg (unlisted singularity)
    LimitCycle,           // length exceeded max_length (the paper's limit-cycle test)
    MaxSteps,             // step budget exhausted
    StartOutside,         // the seed is not inside the mesh
};
const char* to_string(StopReason reason);  // "left_solid" | "singularity" | "sharp_turn" | ...

struct TraceOptions {
    double step = 0;               // RK4 step, model units; 0 = 0.4 x mean edge length
    double max_length = 0;         // model units; 0 = 3 x bbox diagonal (limit cycle)
    int max_steps = 20000;
    double max_turn_deg = 45;      // between consecutive step directions
    // The start direction only picks the nearest field axis, with no turn test against it (a
    // direction guessed from elsewhere, such as a sheet source's tangent). Off: a start more than
    // max_turn_deg off every axis stops as SharpTurn, which drops seeds in a twisted field.
    bool start_picks_axis = false;
    // Points of singular curves (model units, #S x 3) and the distance at which a streamline
    // that has already travelled 2 x stop_distance stops near them (0 = 1.5 x mean edge length).
    Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> singular_points;
    double stop_distance = 0;
    bool append_singular_point = true;  // end a ReachedSingularity streamline ON the nearest curve point
    int threads = 0;               // OpenMP threads for trace_streamlines, 0 = all
};

struct Streamline {
    Points points;                 // #P x 3 polyline, model units; row 0 is the seed
    StopReason reason = StopReason::MaxSteps;
    double length = 0;             // model units
};

// The cheap direction field: per-vertex axis closest to v, averaged with the barycentric weights
// (clamped to >= 0), normalised. `axes` is FrameField::axes (#V x 9, columns of R row by row).
Eigen::Vector3d closest_direction_at(const TetMesh& mesh, const FrameField& field, const TetLocation& where,
                                     const Eigen::Vector3d& v);

// One streamline from `seed` along (roughly) `direction`.
Streamline trace_streamline(const TetMesh& mesh, const FrameField& field, const TetLocator& locator,
                            const Eigen::Vector3d& seed, const Eigen::Vector3d& direction,
                            const TraceOptions& options = {});

// Many streamlines in parallel: seeds and directions are #N x 3; result i belongs to row i.
std::vector<Streamline> trace_streamlines(const TetMesh& mesh, const FrameField& field, const TetLocator& locator,
                                          const Points& seeds, const Points& directions,
                                          const TraceOptions& options = {});

}  // namespace framefix
