// boundary_constraints (docs/algorithms.md#boundary-constraints).
#include <algorithm>
#include <array>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

#include <Eigen/Geometry>

#include "framefix/core/error.h"
#include "framefix/frame_field/frame_field.h"
#include "framefix/mesh/keys.h"

namespace framefix {
namespace {

using Vec3 = Eigen::Vector3d;

// Outward normal of each CAD face around each boundary vertex (area-weighted), and the
// area-weighted normal over all faces.
struct VertexNormals {
    std::vector<std::map<int, Vec3>> by_tag;  // #V: face tag -> normal sum
    std::vector<Vec3> all;                    // #V
};

VertexNormals vertex_normals(const TetMesh& mesh) {
    VertexNormals vn;
    vn.by_tag.resize(mesh.num_vertices());
    vn.all.assign(mesh.num_vertices(), Vec3::Zero());
    const bool tagged = mesh.face_tags.size() == mesh.boundary_faces.rows();
    for (int f = 0; f < mesh.boundary_faces.rows(); ++f) {
        const Vec3 p0 = mesh.points.row(mesh.boundary_faces(f, 0));
        const Vec3 n = (Vec3(mesh.points.row(mesh.boundary_faces(f, 1))) - p0)
                           .cross(Vec3(mesh.points.row(mesh.boundary_faces(f, 2))) - p0);  // 2 x area
        const int tag = tagged ? mesh.face_tags(f) : 0;
        for (int k = 0; k < 3; ++k) {
            const int v = mesh.boundary_faces(f, k);
            vn.all[v] += n;
            auto [it, inserted] = vn.by_tag[v].try_emplace(tag, Vec3::Zero());
            it->second += n;
        }
    }
    return vn;
}

// A feature curve as seen from one vertex: its CAD edge and the unit directions of its mesh edges
// leaving the vertex.
struct CurveAtVertex {
    int curve;
    std::vector<Vec3> out;
};

}  // namespace

Constraints boundary_constraints(const TetMesh& mesh, const FeatureSet& features) {
    const int nv = mesh.num_vertices();
    if (mesh.feature_edges.rows() != mesh.edge_tags.size())
        throw Error("constraints", "the mesh has " + std::to_string(mesh.feature_edges.rows()) + " feature edges but " +
                                       std::to_string(mesh.edge_tags.size()) + " edge tags");
    if (mesh.face_tags.size() != mesh.boundary_faces.rows())
        throw Error("constraints", "the mesh has " + std::to_string(mesh.boundary_faces.rows()) +
                                       " boundary triangles but " + std::to_string(mesh.face_tags.size()) + " face tags");
    const VertexNormals vn = vertex_normals(mesh);

    // CAD faces on either side of each feature curve, ranked by how many of its edges they touch.
    std::unordered_map<PairKey, int> feature_edge_of;
    for (int e = 0; e < mesh.feature_edges.rows(); ++e)
        if (features.valence_of(mesh.edge_tags(e)) > 0) feature_edge_of[edge_key(mesh.feature_edges(e, 0), mesh.feature_edges(e, 1), nv)] = e;
    std::map<int, std::map<int, int>> curve_face_count;  // curve -> face tag -> edges
    for (int f = 0; f < mesh.boundary_faces.rows(); ++f)
        for (int k = 0; k < 3; ++k) {
            auto it = feature_edge_of.find(edge_key(mesh.boundary_faces(f, k), mesh.boundary_faces(f, (k + 1) % 3), nv));
            if (it != feature_edge_of.end()) curve_face_count[mesh.edge_tags(it->second)][mesh.face_tags(f)] += 1;
        }
    std::map<int, std::array<int, 2>> curve_faces;  // only curves with two distinct faces are features
    for (const auto& [curve, counts] : curve_face_count) {
        std::vector<std::pair<int, int>> ranked;  // (-count, tag)
        for (const auto& [tag, n] : counts) ranked.push_back({-n, tag});
        std::sort(ranked.begin(), ranked.end());
        if (ranked.size() >= 2) curve_faces[curve] = {ranked[0].second, ranked[1].second};
    }

    std::vector<std::vector<CurveAtVertex>> at(nv);
    for (int e = 0; e < mesh.feature_edges.rows(); ++e) {
        const int curve = mesh.edge_tags(e);
        if (features.valence_of(curve) <= 0 || !curve_faces.count(curve)) continue;
        const int a = mesh.feature_edges(e, 0), b = mesh.feature_edges(e, 1);
        const Vec3 d = (Vec3(mesh.points.row(b)) - Vec3(mesh.points.row(a))).normalized();
        for (const auto& [v, dir] : {std::pair<int, Vec3>{a, d}, std::pair<int, Vec3>{b, -d}}) {
            auto it = std::find_if(at[v].begin(), at[v].end(), [&](const CurveAtVertex& c) { return c.curve == curve; });
            if (it == at[v].end()) at[v].push_back({curve, {dir}});
            else it->out.push_back(dir);
        }
    }

    Constraints cons;
    cons.kind.assign(nv, ConstraintKind::Free);
    cons.normal = decltype(cons.normal)::Zero(nv, 3);
    cons.fixed = decltype(cons.fixed)::Zero(nv, 9);
    auto fix = [&](int v, const Eigen::Matrix3d& R) {
        cons.kind[v] = ConstraintKind::Fixed;
        cons.fixed.row(v) = frame_from_rotation(R).transpose();
    };
    for (int v = 0; v < nv; ++v) {
        if (vn.all[v].norm() <= 0) continue;  // interior (or on no boundary triangle): free
        cons.kind[v] = ConstraintKind::NormalAligned;
        cons.normal.row(v) = vn.all[v].normalized().transpose();
        auto& curves = at[v];
        if (curves.empty()) continue;
        std::sort(curves.begin(), curves.end(), [](const auto& x, const auto& y) { return x.curve < y.curve; });
        // Tangent of one curve at v: its directions with the sign of the first, summed (the curve
        // passes through v, so the two leaving directions are nearly opposite).
        auto tangent = [](const CurveAtVertex& c) {
            Vec3 t = Vec3::Zero();
            for (const Vec3& d : c.out) t += d.dot(c.out[0]) >= 0 ? d : Vec3(-d);
            return Vec3(t.normalized());
        };
        const bool curve_vertex =
            curves.size() == 1 ||
            (curves.size() == 2 && std::abs(curves[0].out[0].dot(curves[1].out[0])) > 0.9);  // split curve, seam point
        if (curve_vertex) {
            const auto faces = curve_faces.at(curves[0].curve);
            auto n1 = vn.by_tag[v].find(faces[0]), n2 = vn.by_tag[v].find(faces[1]);
            if (n1 == vn.by_tag[v].end() || n2 == vn.by_tag[v].end()) continue;  // curve end on a third face
            const Vec3 t = tangent(curves[0]);
            // A normal parallel to the tangent (the curve runs into a face head-on): keep tangency.
            if (std::abs(n1->second.normalized().dot(t)) > 0.99 || std::abs(n2->second.normalized().dot(t)) > 0.99) continue;
            fix(v, feature_frame(t, n1->second.normalized(), n2->second.normalized()));
        } else if (vn.by_tag[v].size() == 3) {  // a corner with three CAD faces
            auto it = vn.by_tag[v].begin();
            const Vec3 n1 = it->second.normalized(), n2 = (++it)->second.normalized(), n3 = (++it)->second.normalized();
            // Two of the faces may be coplanar (an imprinted curve meeting an edge: a T-junction);
            // the normals then span a plane only and their polar factor is arbitrary. The frame is
            // the one of the crease between the two distinct normals.
            const double c12 = std::abs(n1.dot(n2)), c13 = std::abs(n1.dot(n3)), c23 = std::abs(n2.dot(n3));
            const double most_parallel = std::max({c12, c13, c23});
            if (most_parallel > 0.9) {
                const Vec3 a = n1, b = c12 > 0.9 ? n3 : n2;
                const Vec3 t = a.cross(b);
                if (t.norm() < 0.1) {  // all three parallel: a flat point, leave tangency
                    continue;
                }
                fix(v, feature_frame(t.normalized(), a, b));
            } else {
                fix(v, corner_frame(n1, n2, n3));
            }
        } else {
            cons.kind[v] = ConstraintKind::Free;  // 2 or >= 4 faces: the field decides (singular point)
        }
    }
    return cons;
}

}  // namespace framefix

namespace framefix {

void set_singular(Constraints& cons, int v, const Eigen::Vector3d& axis) {
    if (cons.singular.empty()) cons.singular.assign(cons.kind.size(), 0);
    cons.kind[size_t(v)] = ConstraintKind::Fixed;
    cons.normal.row(v) = axis.normalized().transpose();
    cons.fixed.row(v) = normal_aligned(axis.normalized()).c.transpose();
    cons.singular[size_t(v)] = 1;
}

}  // namespace framefix
