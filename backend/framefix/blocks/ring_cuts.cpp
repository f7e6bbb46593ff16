#include "framefix/blocks/ring_cuts.h"

#include <algorithm>
#include <deque>
#include <string>
#include <unordered_map>

namespace framefix {
namespace {

constexpr double kLoopCloseH = 2;  // a streamline back this close to its start closed the loop
constexpr double kMinLoopH = 6;    // after at least this much travel (a loop round a hole of ~1 h)

// The vertex of block b farthest, in mesh edges, from the block's boundary (-1: none inside).
int deepest_vertex(const TetMesh& mesh, const BlockInfo& block, const std::vector<BoundaryTriangle>& surface) {
    std::unordered_map<int, std::vector<int>> adj;
    for (int t : block.tets)
        for (int i = 0; i < 4; ++i)
            for (int j = i + 1; j < 4; ++j) {
                adj[mesh.tets(t, i)].push_back(mesh.tets(t, j));
                adj[mesh.tets(t, j)].push_back(mesh.tets(t, i));
            }
    std::unordered_map<int, int> depth;
    std::deque<int> queue;
    for (const BoundaryTriangle& tri : surface)
        for (int k = 0; k < 3; ++k)
            if (depth.emplace(tri.verts[k], 0).second) queue.push_back(tri.verts[k]);
    int deepest = -1, best = 0;
    while (!queue.empty()) {
        const int v = queue.front();
        queue.pop_front();
        for (int w : adj[v])
            if (depth.emplace(w, depth[v] + 1).second) {
                queue.push_back(w);
                if (depth[w] > best) best = depth[w], deepest = w;
            }
    }
    return deepest;
}

// Frame axis k (0..2) at p, unit; zero outside the mesh.
Eigen::Vector3d axis_at(const TetMesh& mesh, const FrameField& field, const TetLocator& locator,
                        const Eigen::Vector3d& p, const Eigen::Vector3d& near) {
    const TetLocation where = locator.locate(p);
    if (where.tet < 0) return Eigen::Vector3d::Zero();
    return closest_direction_at(mesh, field, where, near);
}

// The core loop from p along one of the field's axes: the streamline up to its closest return
// to p after kMinLoopH h. Empty when no axis comes back.
Points core_loop(const TetMesh& mesh, const FrameField& field, const TetLocator& locator, const Eigen::Vector3d& p,
                 int vertex, double h, const TraceOptions& trace) {
    for (int k = 0; k < 3; ++k) {
        const Eigen::Vector3d axis(field.axes(vertex, 3 * k), field.axes(vertex, 3 * k + 1), field.axes(vertex, 3 * k + 2));
        const Streamline s = trace_streamline(mesh, field, locator, p, axis, trace);
        double travelled = 0;
        int back = -1;
        double closest = kLoopCloseH * h;
        for (int i = 1; i < int(s.points.rows()); ++i) {
            travelled += (s.points.row(i) - s.points.row(i - 1)).norm();
            const double d = (s.points.row(i).transpose() - p).norm();
            if (travelled > kMinLoopH * h && d < closest) closest = d, back = i;
            if (back >= 0 && d > 2 * closest + h) break;  // past the closest return
        }
        if (back > 0) return s.points.topRows(back + 1);
    }
    return Points();
}

// Point and unit tangent at arc length `at` along the polyline.
void point_at(const Points& P, double at, Eigen::Vector3d& point, Eigen::Vector3d& tangent) {
    double s = 0;
    for (int i = 1; i < int(P.rows()); ++i) {
        const double step = (P.row(i) - P.row(i - 1)).norm();
        if (s + step >= at || i + 1 == int(P.rows())) {
            const double f = step > 0 ? std::clamp((at - s) / step, 0.0, 1.0) : 0.0;
            point = ((1 - f) * P.row(i - 1) + f * P.row(i)).transpose();
            tangent = (P.row(i) - P.row(i - 1)).transpose().normalized();
            return;
        }
        s += step;
    }
}

double length_of(const Points& P) {
    double s = 0;
    for (int i = 1; i < int(P.rows()); ++i) s += (P.row(i) - P.row(i - 1)).norm();
    return s;
}

// The meridian source through q across the loop tangent t: the streamline along the axis `b`
// to the boundary both ways, seeded every h, each seed's sheets along the remaining axis.
SheetSource meridian(const TetMesh& mesh, const FrameField& field, const TetLocator& locator, const Eigen::Vector3d& q,
                     const Eigen::Vector3d& t, double h, const TraceOptions& trace, const std::string& name) {
    SheetSource src;
    src.kind = SheetSource::Ring;
    src.name = name;
    const Eigen::Vector3d along = axis_at(mesh, field, locator, q, t);
    const Eigen::Vector3d guess = std::abs(along.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    const Eigen::Vector3d b = axis_at(mesh, field, locator, q, (guess - guess.dot(along) * along).normalized());
    if (b.isZero()) return src;
    const Streamline up = trace_streamline(mesh, field, locator, q, b, trace);
    const Streamline down = trace_streamline(mesh, field, locator, q, -b, trace);
    std::vector<Eigen::Vector3d> line;
    for (int i = int(down.points.rows()) - 1; i > 0; --i) line.push_back(down.points.row(i).transpose());
    for (int i = 0; i < int(up.points.rows()); ++i) line.push_back(up.points.row(i).transpose());
    src.boundary_end[0] = down.reason == StopReason::LeftSolid;
    src.boundary_end[1] = up.reason == StopReason::LeftSolid;
    double since = h;
    for (size_t i = 0; i < line.size(); ++i) {
        if (i > 0) since += (line[i] - line[i - 1]).norm();
        if (since < h && i + 1 < line.size()) continue;
        since = 0;
        const Eigen::Vector3d tangent = (line[std::min(i + 1, line.size() - 1)] - line[i > 0 ? i - 1 : 0]).normalized();
        const Eigen::Vector3d a = axis_at(mesh, field, locator, line[i], t.cross(tangent));
        if (a.isZero() || !tangent.allFinite()) continue;
        SheetSeed seed;
        seed.point = line[i];
        seed.tangent = tangent;
        seed.directions = {a, -a};
        src.seeds.push_back(std::move(seed));
    }
    return src;
}

}  // namespace

std::vector<SheetSource> ring_sources(const TetMesh& mesh, const FrameField& field, const TetLocator& locator,
                                      const BlockDecomposition& blocks,
                                      const std::vector<std::vector<BoundaryTriangle>>& surface, double h,
                                      const TraceOptions& trace) {
    std::vector<SheetSource> out;
    std::vector<int> rings;
    for (int b = 0; b < blocks.count; ++b)
        if (blocks.blocks[size_t(b)].manifold && blocks.blocks[size_t(b)].euler == 0) rings.push_back(b);
    // Largest first; a ring next to one already cut goes round the same hole, and the meridians,
    // which run to the boundary both ways, cut it too (the torus's core ring and the four around it).
    std::stable_sort(rings.begin(), rings.end(), [&](int a, int b) {
        return blocks.blocks[size_t(a)].tets.size() > blocks.blocks[size_t(b)].tets.size();
    });
    std::vector<char> covered(size_t(blocks.count), 0);
    for (int b : rings) {
        const BlockInfo& info = blocks.blocks[size_t(b)];
        if (covered[size_t(b)]) continue;
        const int v = deepest_vertex(mesh, info, surface[size_t(b)]);
        if (v < 0) continue;
        const Eigen::Vector3d p = mesh.points.row(v).transpose();
        const Points loop = core_loop(mesh, field, locator, p, v, h, trace);
        if (loop.rows() < 2) continue;
        const double length = length_of(loop);
        for (int k = 0; k < kRingCuts; ++k) {
            Eigen::Vector3d q, t;
            point_at(loop, length * (k + 0.5) / kRingCuts, q, t);
            SheetSource src = meridian(mesh, field, locator, q, t, h, trace, "ring:" + std::to_string(b));
            if (src.seeds.size() >= 2) out.push_back(std::move(src));
        }
        for (int o : info.neighbours) covered[size_t(o)] = 1;
    }
    return out;
}

}  // namespace framefix
