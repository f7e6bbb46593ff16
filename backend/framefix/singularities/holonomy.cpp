#include "framefix/singularities/holonomy.h"

#include <cmath>

#include <Eigen/Geometry>

#include <omp.h>

#include "framefix/core/error.h"
#include "framefix/frame_field/projection.h"
#include "framefix/singularities/cube_group.h"

namespace framefix {
namespace {

constexpr double kPi = 3.14159265358979323846;

int thread_count(int requested) { return requested > 0 ? requested : omp_get_max_threads(); }

// Projection of an interpolated sample: warm starts from both edge ends, the closer result wins
// (one start can fall into a local maximum when the ends are far apart).
Eigen::Matrix3d sample_rotation(const SH9& q, const Eigen::Matrix3d& Ra, const Eigen::Matrix3d& Rb,
                                const Eigen::Matrix3d& fallback) {
    if (q.norm() < 1e-8) return fallback;  // no direction information at a zero of the field
    const ProjectedFrame pa = project_frame_from(q, Ra);
    const ProjectedFrame pb = project_frame_from(q, Rb);
    return pb.distance < pa.distance ? pb.rotation : pa.rotation;
}

// Edges of the topology grouped by their smaller vertex (they are sorted), for face -> edge lookup.
struct EdgeIndex {
    std::vector<int> start;  // #V + 1 into topo.edges rows
    const Segments* edges = nullptr;

    int find(int a, int b) const {  // a < b
        for (int e = start[a]; e < start[a + 1]; ++e)
            if ((*edges)(e, 1) == b) return e;
        FF_ASSERT(false);  // every face edge is a topology edge
        return -1;
    }
};

EdgeIndex index_edges(const TetTopology& topo, int nv) {
    EdgeIndex idx;
    idx.edges = &topo.edges;
    idx.start.assign(nv + 1, 0);
    for (int e = 0; e < topo.edges.rows(); ++e) idx.start[topo.edges(e, 0) + 1] += 1;
    for (int v = 0; v < nv; ++v) idx.start[v + 1] += idx.start[v];
    return idx;
}

void check_input(const TetMesh& mesh, const TetTopology& topo, const FrameField& field) {
    const int nv = mesh.num_vertices();
    if (field.coefficients.rows() != nv)
        throw Error("singularities", "the frame field has " + std::to_string(field.coefficients.rows()) +
                                         " rows for a mesh of " + std::to_string(nv) +
                                         " vertices; solve the field on this mesh");
    if (!field.coefficients.allFinite())
        throw Error("singularities", "the frame field has non-finite coefficients; re-run the field solve");
    if (topo.tet_faces.rows() != mesh.num_tets() || topo.on_boundary.size() != size_t(nv))
        throw Error("singularities", "the topology does not belong to this mesh; rebuild it with build_topology");
}

}  // namespace

std::vector<Eigen::Matrix3d> vertex_rotations(const FrameField& field, int threads) {
    const int nv = int(field.coefficients.rows());
    const bool warm = field.axes.rows() == nv;
    std::vector<Eigen::Matrix3d> R(nv);
#pragma omp parallel for schedule(static) num_threads(thread_count(threads))
    for (int v = 0; v < nv; ++v) {
        const SH9 q = field.coefficients.row(v).transpose();
        Eigen::Matrix3d guess = Eigen::Matrix3d::Identity();
        if (warm)
            for (int k = 0; k < 3; ++k) guess.col(k) = field.axes.row(v).segment<3>(3 * k).transpose();
        if (q.norm() < 1e-8)
            R[v] = guess;
        else
            R[v] = warm ? project_frame_from(q, guess).rotation : project_frame(q).rotation;
    }
    return R;
}

int edge_transport(const SH9& qa, const SH9& qb, const Eigen::Matrix3d& Ra, const Eigen::Matrix3d& Rb,
                   double direct_match_deg, bool* subsampled) {
    double c = 1;
    const int direct = cube::match(Ra, Rb, &c);
    const bool direct_ok = direct_match_deg > 0 && c > std::cos(direct_match_deg * kPi / 180);
    if (subsampled) *subsampled = !direct_ok;
    if (direct_ok) return direct;
    const Eigen::Matrix3d R1 = sample_rotation((2 * qa + qb) / 3, Ra, Rb, Ra);
    const Eigen::Matrix3d R2 = sample_rotation((qa + 2 * qb) / 3, R1, Rb, R1);
    // Carry the representative of frame a along a -> 1/3 -> 2/3 -> b.
    Eigen::Matrix3d cur = R1 * cube::matrix(cube::match(Ra, R1));
    cur = R2 * cube::matrix(cube::match(cur, R2));
    return cube::match(cur, Rb);
}

int loop_holonomy(const std::vector<Eigen::Matrix3d>& frames) {
    FF_ASSERT(!frames.empty());
    Eigen::Matrix3d cur = frames[0];
    for (size_t k = 1; k < frames.size(); ++k) cur = frames[k] * cube::matrix(cube::match(cur, frames[k]));
    return cube::match(cur, frames[0]);
}

int loop_valence(int g, const Eigen::Matrix3d& R0, const Eigen::Vector3d& x0, const Eigen::Vector3d& x1,
                 const Eigen::Vector3d& x2, Eigen::Vector3d* axis) {
    const int tr = cube::trace(g);
    const Eigen::Vector3d w = R0 * cube::axis(g);
    if (axis) *axis = w;
    if (tr == 3) return 0;
    if (tr != 1) return -1;  // 120 deg (diagonal axis) or 180 deg: unresolved node material
    return w.dot((x1 - x0).cross(x2 - x0)) > 0 ? 3 : 5;
}

FaceHolonomy face_holonomy(const TetMesh& mesh, const TetTopology& topo, const FrameField& field,
                           const HolonomyOptions& options) {
    check_input(mesh, topo, field);
    const int nv = mesh.num_vertices(), nf = int(topo.faces.rows()), ne = int(topo.edges.rows());
    const int nthreads = thread_count(options.threads);
    const std::vector<Eigen::Matrix3d> R = vertex_rotations(field, options.threads);

    // T[e] carries frame edges(e,0) to frame edges(e,1); computed once per edge, shared by its faces.
    std::vector<signed char> T(ne);
    int subsampled = 0;
#pragma omp parallel for schedule(dynamic, 1024) num_threads(nthreads) reduction(+ : subsampled)
    for (int e = 0; e < ne; ++e) {
        const int a = topo.edges(e, 0), b = topo.edges(e, 1);
        bool sub = false;
        T[e] = static_cast<signed char>(edge_transport(field.coefficients.row(a).transpose(),
                                                       field.coefficients.row(b).transpose(), R[a], R[b],
                                                       options.direct_match_deg, &sub));
        subsampled += sub;
    }

    const EdgeIndex edges = index_edges(topo, nv);
    FaceHolonomy out;
    out.valence.assign(nf, 0);
    out.axis.setZero(nf, 3);
    out.subsampled_edges = subsampled;
#pragma omp parallel for schedule(static) num_threads(nthreads)
    for (int f = 0; f < nf; ++f) {
        const int i0 = topo.faces(f, 0), i1 = topo.faces(f, 1), i2 = topo.faces(f, 2);  // sorted
        const int t01 = T[edges.find(i0, i1)], t12 = T[edges.find(i1, i2)];
        const int t20 = cube::inverse(T[edges.find(i0, i2)]);
        const int g = cube::multiply(t20, cube::multiply(t12, t01));
        if (g == 0) continue;  // identity: regular face
        Eigen::Vector3d w;
        out.valence[f] = loop_valence(g, R[i0], mesh.points.row(i0).transpose(), mesh.points.row(i1).transpose(),
                                      mesh.points.row(i2).transpose(), &w);
        out.axis.row(f) = w.transpose();
    }
    return out;
}

}  // namespace framefix
