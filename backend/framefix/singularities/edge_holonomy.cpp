#include "framefix/singularities/edge_holonomy.h"

#include <array>

#include <omp.h>

#include "framefix/frame_field/projection.h"
#include "framefix/singularities/chain_ends.h"
#include "framefix/singularities/cube_group.h"
#include "framefix/singularities/holonomy.h"

namespace framefix {
namespace {

// A mean coefficient vector this far from the frame manifold may sit in a local minimum of the
// projection started from one vertex: the other three vertices are tried too. Distance units
// of ProjectedFrame (0 on the manifold, ~1.3 at most).
constexpr double kRetryDistance = 0.3;

int thread_count(int requested) { return requested > 0 ? requested : omp_get_max_threads(); }

// The two tets beyond the faces of t that hold edge (a, b); -1 beyond the boundary.
std::array<int, 2> ring_neighbours(const TetMesh& mesh, const TetTopology& topo, int t, int a, int b) {
    std::array<int, 2> n{-2, -2};
    int k = 0;
    for (int lv = 0; lv < 4; ++lv) {
        const int v = mesh.tets(t, lv);
        if (v == a || v == b) continue;
        n[size_t(k++)] = tet_across(topo, topo.tet_faces(t, lv), t);  // face lf = lv is opposite vertex lv
    }
    return n;
}

bool has_vertex(const TetMesh& mesh, int t, int v) {
    for (int k = 0; k < 4; ++k)
        if (mesh.tets(t, k) == v) return true;
    return false;
}

int ring_valence(const TetMesh& mesh, const TetTopology& topo, const std::vector<Eigen::Matrix3d>& R, int e,
                 const std::vector<int>& ring, Eigen::Vector3d* axis) {
    std::vector<Eigen::Matrix3d> frames;
    for (int t : ring) frames.push_back(R[size_t(t)]);
    const int g = loop_holonomy(frames);
    if (cube::trace(g) == 3) return 0;
    const Eigen::Vector3d xa = mesh.points.row(topo.edges(e, 0)).transpose();
    const Eigen::Vector3d d = mesh.points.row(topo.edges(e, 1)).transpose() - xa;
    double turn = 0;  // > 0 when the ring turns right-handed about d
    for (size_t i = 0; i < ring.size(); ++i)
        turn += (tet_centroid(mesh, ring[i]) - xa).cross(tet_centroid(mesh, ring[(i + 1) % ring.size()]) - xa).dot(d);
    // Reversing the ring inverts g and flips its axis: this is the axis for the ring right-handed about d.
    *axis = (turn > 0 ? 1.0 : -1.0) * (R[size_t(ring[0])] * cube::axis(g));
    if (cube::trace(g) != 1) return -1;  // 120 or 180 deg: node material
    return axis->dot(d) > 0 ? 3 : 5;
}

}  // namespace

std::vector<Eigen::Matrix3d> tet_rotations(const TetMesh& mesh, const FrameField& field,
                                           const std::vector<Eigen::Matrix3d>& vertex_rotation, int threads) {
    const int nt = mesh.num_tets();
    std::vector<Eigen::Matrix3d> R(static_cast<size_t>(nt));
#pragma omp parallel for schedule(static) num_threads(thread_count(threads))
    for (int t = 0; t < nt; ++t) {
        SH9 q = SH9::Zero();
        for (int k = 0; k < 4; ++k) q += field.coefficients.row(mesh.tets(t, k)).transpose();
        ProjectedFrame best = project_frame_from(q, vertex_rotation[size_t(mesh.tets(t, 0))]);
        for (int k = 1; k < 4 && best.distance > kRetryDistance; ++k) {
            const ProjectedFrame p = project_frame_from(q, vertex_rotation[size_t(mesh.tets(t, k))]);
            if (p.distance < best.distance) best = p;
        }
        R[size_t(t)] = best.rotation;
    }
    return R;
}

std::vector<int> edge_ring(const TetMesh& mesh, const TetTopology& topo, int e) {
    const int a = topo.edges(e, 0), b = topo.edges(e, 1);
    int start = -1, count = 0;
    for (int k = topo.vert_tets_start[a]; k < topo.vert_tets_start[a + 1]; ++k)
        if (has_vertex(mesh, topo.vert_tets[k], b)) {
            if (start < 0) start = topo.vert_tets[k];
            ++count;
        }
    std::vector<int> ring;
    if (start < 0) return ring;
    int prev = -1, cur = start;
    do {
        ring.push_back(cur);
        const std::array<int, 2> n = ring_neighbours(mesh, topo, cur, a, b);
        if (n[0] < 0 || n[1] < 0) return {};  // an open fan: the edge is on the boundary
        const int next = n[0] != prev ? n[0] : n[1];
        prev = cur, cur = next;
    } while (cur != start && int(ring.size()) <= count);
    if (cur != start) return {};  // not a closed ring (a non-manifold mesh)
    return ring;
}

EdgeHolonomy edge_holonomy(const TetMesh& mesh, const TetTopology& topo, const FrameField& field, int threads) {
    const std::vector<Eigen::Matrix3d> R = tet_rotations(mesh, field, vertex_rotations(field, threads), threads);
    const int ne = int(topo.edges.rows());
    EdgeHolonomy out;
    out.valence.assign(size_t(ne), 0);
    out.axis.setZero(ne, 3);
#pragma omp parallel for schedule(dynamic, 1024) num_threads(thread_count(threads))
    for (int e = 0; e < ne; ++e) {
        const std::vector<int> ring = edge_ring(mesh, topo, e);
        if (ring.size() < 3) continue;
        Eigen::Vector3d w = Eigen::Vector3d::Zero();
        out.valence[size_t(e)] = ring_valence(mesh, topo, R, e, ring, &w);
        out.axis.row(e) = w.transpose();
    }
    return out;
}

}  // namespace framefix
