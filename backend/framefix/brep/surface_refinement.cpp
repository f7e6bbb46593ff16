#include "framefix/brep/surface_refinement.h"

#include <cmath>
#include <queue>
#include <utility>

#include <Eigen/Geometry>

#include "framefix/core/error.h"

namespace framefix {
namespace {

using Key = PairKey;  // edge_key(a, b, kAnyIdStride)

constexpr double kFlipNormalCos = 0.9;  // flipped triangles within ~25 deg of the surface normal

struct Refiner {
    TaggedSurface& s;
    const SurfaceEvaluator& eval;
    std::unordered_map<Key, std::vector<int>> edge_tris;  // mesh edge -> triangles holding it
    // (length x max_edge / bound, edge), most over first; exactly the length where bound = max_edge
    std::priority_queue<std::pair<double, Key>> queue;
    std::vector<Key> to_check;                             // edges whose Delaunay property may be broken
    long flips_left = 0;                                   // guards against flip cycles on curved faces
    double max_edge = 0;
    const std::vector<double>& face_max_edge;

    double bound(int face) const {
        const size_t f = size_t(face);
        return f < face_max_edge.size() && face_max_edge[f] > 0 ? std::min(max_edge, face_max_edge[f]) : max_edge;
    }

    double length(int a, int b) const { return (s.points[size_t(a)] - s.points[size_t(b)]).norm(); }

    void link(int tri) {
        const auto& v = s.triangles[size_t(tri)].v;
        for (int k = 0; k < 3; ++k) {
            const int a = v[size_t(k)], b = v[size_t((k + 1) % 3)];
            const Key key = edge_key(a, b, kAnyIdStride);
            std::vector<int>& tris = edge_tris[key];
            // Pushed again by a second face with a smaller bound; a split edge's entries are skipped.
            const double b_face = bound(s.triangles[size_t(tri)].face);
            if (tris.empty() || b_face < bound(s.triangles[size_t(tris[0])].face))
                queue.push({length(a, b) * (max_edge / b_face), key});
            tris.push_back(tri);
        }
    }

    void unlink(int tri) {
        const auto& v = s.triangles[size_t(tri)].v;
        for (int k = 0; k < 3; ++k) {
            const Key key = edge_key(v[size_t(k)], v[size_t((k + 1) % 3)], kAnyIdStride);
            auto it = edge_tris.find(key);
            if (it == edge_tris.end()) continue;
            auto& tris = it->second;
            for (size_t i = 0; i < tris.size(); ++i)
                if (tris[i] == tri) {
                    tris.erase(tris.begin() + long(i));
                    break;
                }
            if (tris.empty()) edge_tris.erase(it);
        }
    }

    // Position of the directed edge a -> b (either direction) in triangle `tri`, 3 if absent.
    size_t find_edge(const TaggedSurface::Triangle& t, int a, int b) const {
        for (size_t k = 0; k < 3; ++k) {
            const int p = t.v[k], q = t.v[(k + 1) % 3];
            if ((p == a && q == b) || (p == b && q == a)) return k;
        }
        return 3;
    }

    double angle(int apex, int p, int q) const {
        const Eigen::Vector3d u = s.points[size_t(p)] - s.points[size_t(apex)];
        const Eigen::Vector3d v = s.points[size_t(q)] - s.points[size_t(apex)];
        return std::atan2(u.cross(v).norm(), u.dot(v));
    }

    Eigen::Vector3d normal(int a, int b, int c) const {
        return (s.points[size_t(b)] - s.points[size_t(a)]).cross(s.points[size_t(c)] - s.points[size_t(a)]);
    }

    bool follows_surface(int face, const Eigen::Vector3d& n, const Eigen::Vector2d& uv) const {
        const Eigen::Vector3d ref = eval.normal(face, uv);
        return ref.squaredNorm() == 0 || n.dot(ref) > kFlipNormalCos * n.norm();
    }

    // Lawson flip of the edge if the two triangles of one face around it are not Delaunay
    // (opposite angles sum over pi) and the flipped pair does not fold.
    void legalize(Key key) {
        const auto it = edge_tris.find(key);
        if (it == edge_tris.end() || it->second.size() != 2 || s.curve_edges.count(key) || flips_left <= 0) return;
        const int t1 = it->second[0], t2 = it->second[1];
        TaggedSurface::Triangle A = s.triangles[size_t(t1)], B = s.triangles[size_t(t2)];
        if (A.face != B.face) return;
        const auto [a0, b0] = key_ids(key, kAnyIdStride);
        const size_t ka = find_edge(A, a0, b0), kb = find_edge(B, a0, b0);
        FF_ASSERT(ka < 3 && kb < 3);
        // A = (a, b, c) with the edge a -> b; B = (b, a, d).
        const int a = A.v[ka], b = A.v[(ka + 1) % 3], c = A.v[(ka + 2) % 3];
        const int d = B.v[(kb + 2) % 3];
        if (c == d || angle(c, a, b) + angle(d, b, a) <= 3.14159265358979 + 1e-9) return;
        if (edge_tris.count(edge_key(c, d, kAnyIdStride))) return;
        const Eigen::Vector3d n_old = normal(a, b, c).normalized() + normal(b, a, d).normalized();
        const Eigen::Vector3d n1 = normal(a, d, c), n2 = normal(d, b, c);
        if (n1.dot(n_old) <= 0.5 * n1.norm() * n_old.norm() || n2.dot(n_old) <= 0.5 * n2.norm() * n_old.norm()) return;
        const Eigen::Vector2d uv_a = A.uv[ka], uv_b = A.uv[(ka + 1) % 3], uv_c = A.uv[(ka + 2) % 3];
        const Eigen::Vector2d uv_d = B.uv[(kb + 2) % 3];
        // The flipped triangles must still follow the true surface, or repeated flips on a
        // curved face drift into chords across the solid.
        if (!follows_surface(A.face, n1, (uv_a + uv_d + uv_c) / 3) || !follows_surface(A.face, n2, (uv_d + uv_b + uv_c) / 3))
            return;
        unlink(t1);
        unlink(t2);
        A.v = {a, d, c};
        A.uv = {uv_a, uv_d, uv_c};
        B.v = {d, b, c};
        B.uv = {uv_d, uv_b, uv_c};
        s.triangles[size_t(t1)] = A;
        s.triangles[size_t(t2)] = B;
        link(t1);
        link(t2);
        --flips_left;
        for (Key k : {edge_key(a, d, kAnyIdStride), edge_key(d, b, kAnyIdStride), edge_key(b, c, kAnyIdStride),
                      edge_key(c, a, kAnyIdStride)})
            to_check.push_back(k);
    }

    void legalize_all() {
        while (!to_check.empty()) {
            const Key k = to_check.back();
            to_check.pop_back();
            legalize(k);
        }
    }

    bool halves(const Eigen::Vector3d& p, int a, int b) const {
        const Eigen::Vector3d pa = s.points[size_t(a)], pb = s.points[size_t(b)];
        const double len = (pa - pb).norm();
        return (p - pa).norm() < 0.8 * len && (p - pb).norm() < 0.8 * len;
    }

    void split(int a, int b) {
        const Key key = edge_key(a, b, kAnyIdStride);
        const std::vector<int> tris = edge_tris.at(key);
        const auto curve = s.curve_edges.find(key);
        const bool on_curve = curve != s.curve_edges.end();
        TaggedSurface::CurveEdge ce;
        double t_mid = 0;
        if (on_curve) {
            ce = curve->second;
            t_mid = 0.5 * (ce.t_lo + ce.t_hi);
        }
        const int m = int(s.points.size());
        bool placed = false, projected = false;
        for (int tri : tris) {
            unlink(tri);
            TaggedSurface::Triangle t = s.triangles[size_t(tri)];
            size_t i0 = 3;  // the split edge is v[i0] -> v[i1]
            for (size_t k = 0; k < 3; ++k) {
                const int p = t.v[k], q = t.v[(k + 1) % 3];
                if ((p == a && q == b) || (p == b && q == a)) i0 = k;
            }
            FF_ASSERT(i0 < 3);
            const size_t i1 = (i0 + 1) % 3;
            Eigen::Vector2d uv = 0.5 * (t.uv[i0] + t.uv[i1]);
            if (on_curve) uv = eval.edge_uv(ce.edge, t.face, t_mid, uv);
            if (!placed) {
                Eigen::Vector3d p = on_curve ? eval.on_edge(ce.edge, t_mid) : eval.on_face(t.face, uv);
                if (!halves(p, a, b) && !on_curve) {
                    // The corners' parameters lie in different copies of the domain (a pole, a
                    // seam): the surface point nearest the chord's midpoint halves the edge.
                    p = eval.on_face(t.face, eval.project(t.face, 0.5 * (s.points[size_t(a)] + s.points[size_t(b)]), uv));
                    projected = true;
                }
                // Still no halving point: the chord midpoint, rather than split forever.
                if (!halves(p, a, b)) p = 0.5 * (s.points[size_t(a)] + s.points[size_t(b)]);
                s.points.push_back(p);
                placed = true;
            }
            if (projected) uv = eval.project(t.face, s.points[size_t(m)], uv);
            TaggedSurface::Triangle first = t, second = t;
            first.v[i1] = m;
            first.uv[i1] = uv;
            second.v[i0] = m;
            second.uv[i0] = uv;
            s.triangles[size_t(tri)] = first;
            s.triangles.push_back(second);
            link(tri);
            link(int(s.triangles.size()) - 1);
            const int apex = t.v[(i1 + 1) % 3];  // the corner opposite the split edge
            to_check.push_back(edge_key(t.v[i0], apex, kAnyIdStride));
            to_check.push_back(edge_key(t.v[i1], apex, kAnyIdStride));
        }
        if (on_curve) {
            s.curve_edges.erase(key);
            const double ta = a < b ? ce.t_lo : ce.t_hi, tb = a < b ? ce.t_hi : ce.t_lo;
            // m is the highest index so far: it is the "hi" end of both halves.
            s.curve_edges[edge_key(a, m, kAnyIdStride)] = {ce.edge, ta, t_mid};
            s.curve_edges[edge_key(b, m, kAnyIdStride)] = {ce.edge, tb, t_mid};
        }
    }
};

}  // namespace

void refine_surface(TaggedSurface& surface, const SurfaceEvaluator& eval, double max_edge, int max_points,
                    const std::vector<double>& face_max_edge) {
    Refiner r{surface, eval, {}, {}, {}, 0, max_edge, face_max_edge};
    for (int t = 0; t < int(surface.triangles.size()); ++t) r.link(t);
    r.flips_left = 100L * long(surface.triangles.size()) + 100L * long(std::max(0, max_points));
    for (const auto& entry : r.edge_tris) r.to_check.push_back(entry.first);
    r.legalize_all();
    const size_t limit = surface.points.size() + size_t(std::max(0, max_points));
    while (!r.queue.empty() && surface.points.size() < limit) {
        const auto [scaled_length, key] = r.queue.top();
        r.queue.pop();
        if (scaled_length <= max_edge) break;
        if (r.edge_tris.find(key) == r.edge_tris.end()) continue;  // split already
        const auto [a, b] = key_ids(key, kAnyIdStride);
        r.split(a, b);
        r.legalize_all();
    }
}

}  // namespace framefix
