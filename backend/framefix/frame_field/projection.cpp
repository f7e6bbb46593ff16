// Multi-start Riemannian Newton projection onto the frame manifold (docs/algorithms.md#projection-onto-frames).
#include "framefix/frame_field/projection.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>

#include <Eigen/Cholesky>

#include "framefix/core/error.h"

namespace framefix {
namespace {

constexpr int kCandidates = 48;

struct Candidates {
    std::array<Eigen::Matrix3d, kCandidates> R;
    std::array<SH9, kCandidates> q;
};

// 48 fixed pseudo-random rotations (uniform quaternions, Shoemake) from a fixed seed: the
// standard library's engines are specified bit for bit, its distributions are not.
const Candidates& candidates() {
    static const Candidates c = [] {
        Candidates out;
        std::mt19937 rng(11);
        auto uniform = [&] { return double(rng()) / 4294967296.0; };
        const double two_pi = 6.283185307179586;
        for (int k = 0; k < kCandidates; ++k) {
            const double u1 = uniform(), u2 = uniform(), u3 = uniform();
            const Eigen::Quaterniond quat(std::sqrt(u1) * std::cos(two_pi * u3), std::sqrt(1 - u1) * std::sin(two_pi * u2),
                                          std::sqrt(1 - u1) * std::cos(two_pi * u2), std::sqrt(u1) * std::sin(two_pi * u3));
            out.R[k] = quat.normalized().toRotationMatrix();
            out.q[k] = frame_from_rotation(out.R[k]);
        }
        return out;
    }();
    return c;
}

Eigen::Matrix3d rodrigues(const Eigen::Vector3d& w) {
    const double angle = w.norm();
    if (angle < 1e-300) return Eigen::Matrix3d::Identity();
    return Eigen::AngleAxisd(angle, w / angle).toRotationMatrix();
}

// L v for the three generators (each L_i is sparse; the dense 9x9 product is still a few ns).
inline void apply_generators(const SH9& v, SH9 (&Lv)[3]) {
    for (int i = 0; i < 3; ++i) Lv[i].noalias() = sh_generator(i).lazyProduct(v);  // unrolled, not GEMV
}

struct NewtonResult {
    Eigen::Matrix3d R;
    SH9 v;
    double dot;
};

// Maximise <qn, D(R) f_ref> from R. With Lq_i = L_i qn (antisymmetry of L_i):
//   g_i = <qn, L_i v>,   H_ij = 1/2 <qn, (L_i L_j + L_j L_i) v> = -1/2 (<Lq_i, L_j v> + <Lq_j, L_i v>).
NewtonResult newton(const SH9& qn, const SH9 (&Lq)[3], Eigen::Matrix3d R, const ProjectionOptions& o) {
    SH9 v = frame_from_rotation(R);
    for (int it = 0; it < o.max_iterations; ++it) {
        SH9 Lv[3];
        apply_generators(v, Lv);
        Eigen::Vector3d g;
        Eigen::Matrix3d H;
        for (int i = 0; i < 3; ++i) {
            g(i) = qn.dot(Lv[i]);
            for (int j = 0; j <= i; ++j) H(i, j) = H(j, i) = -0.5 * (Lq[i].dot(Lv[j]) + Lq[j].dot(Lv[i]));
        }
        if (g.norm() < o.tolerance) break;
        Eigen::Vector3d w;
        Eigen::LLT<Eigen::Matrix3d> negH(-H);
        if (negH.info() == Eigen::Success) w = negH.solve(g);  // -H^{-1} g: Newton at a concave point
        else w = g / 8.0;                                      // not concave yet: gradient ascent
        const double len = w.norm();
        if (len > 0.5) w *= 0.5 / len;
        R = rodrigues(w) * R;
        v = frame_from_rotation(R);
    }
    return {R, v, qn.dot(v)};
}

ProjectedFrame finish(const NewtonResult& best, const SH9& qn) {
    ProjectedFrame f;
    f.rotation = best.R;
    f.q = best.v;
    f.distance = (qn - best.v).norm();  // not sqrt(2 - 2 dot): that loses half the digits near 0
    return f;
}

Eigen::Matrix3d orthonormalized(const Eigen::Matrix3d& R) {
    Eigen::Matrix3d Q;
    Q.col(0) = R.col(0).normalized();
    Q.col(1) = (R.col(1) - R.col(1).dot(Q.col(0)) * Q.col(0)).normalized();
    Q.col(2) = Q.col(0).cross(Q.col(1));
    return Q;
}

}  // namespace

ProjectedFrame project_frame(const SH9& q, const ProjectionOptions& options) {
    return project_frame_from(q, nullptr, options);
}

ProjectedFrame project_frame_from(const SH9& q, const Eigen::Matrix3d& warm, const ProjectionOptions& options) {
    return project_frame_from(q, &warm, options);
}

ProjectedFrame project_frame_from(const SH9& q, const Eigen::Matrix3d* warm, const ProjectionOptions& options) {
    const double norm = q.norm();
    if (norm < 1e-8) {
        ProjectedFrame f;
        f.q = reference_frame();
        f.distance = std::sqrt(2.0);
        f.defined = false;
        if (warm) {
            f.rotation = orthonormalized(*warm);
            f.q = frame_from_rotation(f.rotation);
        }
        return f;
    }
    const SH9 qn = q / norm;
    SH9 Lq[3];
    apply_generators(qn, Lq);

    NewtonResult best{Eigen::Matrix3d::Identity(), SH9::Zero(), -2.0};
    if (warm) best = newton(qn, Lq, orthonormalized(*warm), options);

    const int starts = std::min(warm ? options.starts_with_warm : options.starts, kCandidates);
    if (starts > 0) {
        const Candidates& c = candidates();
        std::array<std::pair<double, int>, kCandidates> order;
        for (int k = 0; k < kCandidates; ++k) order[k] = {-qn.dot(c.q[k]), k};
        std::partial_sort(order.begin(), order.begin() + starts, order.end());
        for (int s = 0; s < starts; ++s) {
            // A warm start already at the manifold point of q (distance ~0) cannot be beaten.
            if (best.dot > 1.0 - 1e-12) break;
            const NewtonResult r = newton(qn, Lq, c.R[order[s].second], options);
            if (r.dot > best.dot + 1e-14) best = r;
        }
    }
    return finish(best, qn);
}

Eigen::Vector3d closest_direction(const Eigen::Vector3d& v, const Eigen::Matrix3d& R) {
    int best = 0;
    double best_dot = 0;
    for (int k = 0; k < 3; ++k) {
        const double d = v.dot(R.col(k));
        if (std::abs(d) > std::abs(best_dot)) {
            best_dot = d;
            best = k;
        }
    }
    return best_dot < 0 ? Eigen::Vector3d(-R.col(best)) : Eigen::Vector3d(R.col(best));
}

Eigen::Matrix3d match_frame(const Eigen::Matrix3d& Ra, const Eigen::Matrix3d& Rb) {
    return Rb * octahedral_group()[match_index(Ra, Rb)];
}

int match_index(const Eigen::Matrix3d& Ra, const Eigen::Matrix3d& Rb) {
    // trace(Ra^T Rb g) = sum_ij M_ij g_ji with M = Ra^T Rb; g has one signed 1 per row.
    const Eigen::Matrix3d M = Ra.transpose() * Rb;
    const auto& group = octahedral_group();
    int best = 0;
    double best_trace = -4;
    for (int k = 0; k < 24; ++k) {
        const double tr = (M * group[k]).trace();
        if (tr > best_trace + 1e-12) {
            best_trace = tr;
            best = k;
        }
    }
    return best;
}

}  // namespace framefix
