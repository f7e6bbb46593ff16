#pragma once
// Longest-edge bisection of a face-tagged surface triangulation until no edge is longer than a
// bound, with every new point put on the true geometry: on the B-rep edge curve for mesh edges
// lying on a curve, on the face's surface otherwise. This turns OCCT's deflection-driven
// triangulation (long slivers on planes and cylinders) into one of edge length ~h, which is what
// lets TetGen mesh near-uniformly without refining around slivers.
#include <array>
#include <cstdint>
#include <functional>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "framefix/mesh/keys.h"

namespace framefix {

struct TaggedSurface {
    struct Triangle {
        std::array<int, 3> v;               // point indices, outward
        std::array<Eigen::Vector2d, 3> uv;  // surface parameters of each corner on `face`
        int face = 0;                       // B-rep face index, 1-based
    };
    struct CurveEdge {
        int edge = 0;              // B-rep edge index, 1-based
        double t_lo = 0, t_hi = 0; // curve parameter at the lower / higher point index
    };
    std::vector<Eigen::Vector3d> points;  // model units; B-rep vertices first
    std::vector<Triangle> triangles;
    // Mesh edges on B-rep edges, keyed edge_key(a, b, kAnyIdStride) (points are added while keyed).
    std::unordered_map<PairKey, CurveEdge> curve_edges;
};

struct SurfaceEvaluator {
    std::function<Eigen::Vector3d(int face, const Eigen::Vector2d& uv)> on_face;
    std::function<Eigen::Vector3d(int edge, double t)> on_edge;
    // Outward unit normal of `face` at uv; zero where undefined (poles, apexes).
    std::function<Eigen::Vector3d(int face, const Eigen::Vector2d& uv)> normal;
    // Parameters on `face` of the point at parameter t of `edge`; near_uv picks the side of a seam.
    std::function<Eigen::Vector2d(int edge, int face, double t, const Eigen::Vector2d& near_uv)> edge_uv;
    // Parameters on `face` of the surface point nearest p, searched from near_uv.
    std::function<Eigen::Vector2d(int face, const Eigen::Vector3d& p, const Eigen::Vector2d& near_uv)> project;
};

// Splits edges longer than max_edge (model units), longest first, each split bisecting both
// triangles of the edge. Stops after max_points new points (the caller sized the budget).
// face_max_edge[f] > 0 is a smaller bound on face f (indexed by face, any length); an edge
// between two faces takes the smaller one.
void refine_surface(TaggedSurface& surface, const SurfaceEvaluator& eval, double max_edge, int max_points,
                    const std::vector<double>& face_max_edge = {});

}  // namespace framefix
