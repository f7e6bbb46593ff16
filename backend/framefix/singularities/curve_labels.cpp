#include "framefix/singularities/curve_labels.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include <Eigen/Geometry>

#include "framefix/singularities/chain_ends.h"

namespace framefix {
namespace {

constexpr size_t kTangentReach = 2;  // elements on either side of one that set the curve's tangent

struct Element {
    Eigen::Vector3d position;
    Eigen::Vector3d normal;  // the direction the element's own label is read against
};

// Relabels curve c: sign(i) is +1 when element i is travelled along its normal.
void relabel(const ChainCurve& c, const std::function<Element(int)>& element, const std::function<int(size_t)>& sign,
             const AxisRows& axis, std::vector<int>& valence) {
    const size_t n = c.faces.size();
    std::vector<Element> el;
    for (int f : c.faces) el.push_back(element(f));
    for (size_t i = 0; i < n; ++i) {
        const int f = c.faces[i];
        if (valence[size_t(f)] != 3 && valence[size_t(f)] != 5) continue;
        const int s = sign(i);
        Eigen::Vector3d tangent = s * el[i].normal;
        if (n > 1) {
            const size_t ahead = c.closed ? (i + kTangentReach) % n : std::min(i + kTangentReach, n - 1);
            const size_t behind = c.closed ? (i + n - kTangentReach % n) % n : (i >= kTangentReach ? i - kTangentReach : 0);
            const Eigen::Vector3d t = el[ahead].position - el[behind].position;
            if (t.norm() > 0) tangent = t;
        }
        // The reading against the direction less perpendicular to the axis wins: the tangent on a
        // grazing triangle or a step, the element's own normal where the axis turns away from
        // the curve (a 3-5 transition next to the boundary).
        const Eigen::Vector3d w = axis.row(f).transpose();
        if (std::abs(w.dot(tangent.normalized())) > std::abs(w.dot(el[i].normal.normalized())))
            valence[size_t(f)] = s * w.dot(tangent) > 0 ? 3 : 5;
    }
}

int shared_vertex(const TetTopology& topo, int e, int f) {
    for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b)
            if (topo.edges(e, a) == topo.edges(f, b)) return topo.edges(e, a);
    return -1;
}

int shared_tet(const TetTopology& topo, int f, int g) {
    for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b)
            if (topo.face_tets(f, a) >= 0 && topo.face_tets(f, a) == topo.face_tets(g, b)) return topo.face_tets(f, a);
    return -1;
}

}  // namespace

void label_faces_along_curves(const TetMesh& mesh, const TetTopology& topo, const ChainGraph& graph,
                              const AxisRows& face_axis, std::vector<int>& face_valence) {
    auto element = [&](int f) {
        const Eigen::Vector3d x0 = mesh.points.row(topo.faces(f, 0)).transpose();
        const Eigen::Vector3d n = (mesh.points.row(topo.faces(f, 1)).transpose() - x0)
                                      .cross(mesh.points.row(topo.faces(f, 2)).transpose() - x0);
        return Element{detail::face_centroid(mesh, topo, f), n};
    };
    for (const ChainCurve& c : graph.curves) {
        const size_t n = c.faces.size();
        auto sign = [&](size_t i) {
            const int f = c.faces[i];
            const Element e = element(f);
            const bool wrap = c.closed && n > 2;
            // The tet the curve enters next lies on the normal's side: travel along the normal.
            if (i + 1 < n || wrap) {
                const int t = shared_tet(topo, f, c.faces[(i + 1) % n]);
                if (t >= 0) return (tet_centroid(mesh, t) - e.position).dot(e.normal) > 0 ? 1 : -1;
            }
            if (i > 0 || wrap) {
                const int t = shared_tet(topo, f, c.faces[(i + n - 1) % n]);
                if (t >= 0) return (tet_centroid(mesh, t) - e.position).dot(e.normal) > 0 ? -1 : 1;
            }
            return 1;  // a lone triangle, or a join through a node: its own label
        };
        relabel(c, element, sign, face_axis, face_valence);
    }
}

void label_edges_along_curves(const TetMesh& mesh, const TetTopology& topo, const ChainGraph& graph,
                              const AxisRows& edge_axis, std::vector<int>& edge_valence) {
    auto element = [&](int e) {
        const Eigen::Vector3d a = mesh.points.row(topo.edges(e, 0)).transpose();
        const Eigen::Vector3d b = mesh.points.row(topo.edges(e, 1)).transpose();
        return Element{(a + b) / 2, b - a};
    };
    for (const ChainCurve& c : graph.curves) {
        const size_t n = c.faces.size();
        auto sign = [&](size_t i) {
            const int e = c.faces[i];
            const bool wrap = c.closed && n > 2;
            if (i + 1 < n || wrap) {
                const int to = shared_vertex(topo, e, c.faces[(i + 1) % n]);
                if (to >= 0) return to == topo.edges(e, 1) ? 1 : -1;
            }
            if (i > 0 || wrap) {
                const int from = shared_vertex(topo, e, c.faces[(i + n - 1) % n]);
                if (from >= 0) return from == topo.edges(e, 0) ? 1 : -1;
            }
            return 1;  // a lone edge, or a join through a node: its own direction
        };
        relabel(c, element, sign, edge_axis, edge_valence);
    }
}

}  // namespace framefix
