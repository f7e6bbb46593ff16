#pragma once
// What the two extrusions share: tracing with the reasons a streamline is not used, and the
// choice of the points to insert. Internal to corrections/extrusion*.cpp.
#include <chrono>
#include <string>
#include <vector>

#include "framefix/corrections/extrusion.h"
#include "framefix/streamlines/tet_locator.h"

namespace framefix::detail {

inline double since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// Streamlines from seeds along dirs; used = left the solid, else failure = the stop reason in words.
std::vector<ExtrusionStreamline> trace(const TetMesh& mesh, const FrameField& field, const TetLocator& locator,
                                       const std::vector<Eigen::Vector3d>& seeds, const std::vector<Eigen::Vector3d>& dirs,
                                       const TraceOptions& to, const std::string& source);

// Stops at the singular curves the correction keeps (all but 3-5 and short or mixed curves).
TraceOptions trace_options(const SingularityGraph& graph, const ExtrusionOptions& o);

// Unit direction of polyline point k (central difference), zero when degenerate.
Eigen::Vector3d along(const Points& p, Eigen::Index k);

// Candidate points with their axes, kept greedily in order when far enough from the boundary
// and from the points kept before them; select() fills plan.points and plan.axes.
struct Candidates {
    std::vector<Eigen::Vector3d> points, axes;
    void select(const TetMesh& mesh, double h, const ExtrusionOptions& o, ExtrusionPlan& plan) const;
};

}  // namespace framefix::detail
