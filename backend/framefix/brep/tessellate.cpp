// OCCT surface triangulation of the solid as a watertight PLC for TetGen: B-rep vertices first,
// every B-rep edge discretised once and shared by its faces, triangles outward and face-tagged,
// feature edges as tagged segments.
#include <algorithm>
#include <cmath>
#include <vector>

#include <map>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Curve2d.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <BRepGProp_Face.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Tool.hxx>
#include <IMeshTools_Parameters.hxx>
#include <Poly_PolygonOnTriangulation.hxx>
#include <Poly_Triangulation.hxx>
#include <ShapeAnalysis_Surface.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include "framefix/brep/occt_error.h"
#include "framefix/brep/shape.h"
#include "framefix/brep/surface_refinement.h"
#include "framefix/mesh/size_model.h"

namespace framefix {
namespace {

// OCCT's triangulation only seeds the surface: deflection h/10 and 0.5 rad put every B-rep edge
// and curved face within a small fraction of h; refine_surface then brings every edge to at most
// kMaxEdge * h with points on the true geometry. With TetGen's -Y these surface triangles are
// the boundary of the tet mesh; 1.3 h gives a median tet edge of ~h (bench/bench_mesh).
constexpr double kDeflectionDivisor = 10.0;
constexpr double kAngleRad = 0.5;
constexpr double kMaxEdge = 1.3;

struct Builder {
    TaggedSurface surface;
    std::vector<std::vector<int>> edge_nodes;     // per B-rep edge (1-based), point ids along its polygon
    std::vector<std::vector<double>> edge_params;  // ... and the curve parameter of each

    int add(const Eigen::Vector3d& p) {
        surface.points.push_back(p);
        return int(surface.points.size()) - 1;
    }
};

Eigen::Vector3d node(const Handle(Poly_Triangulation)& tri, int i, const TopLoc_Location& loc) {
    const gp_Pnt p = tri->Node(i).Transformed(loc.Transformation());
    return {p.X(), p.Y(), p.Z()};
}

// Point ids of an edge's polygon, created from the first face that holds it.
void discretise_edge(Builder& b, const BrepModel::Shape& shape, const TopoDS_Edge& edge, int e,
                     const Handle(Poly_PolygonOnTriangulation)& poly, const Handle(Poly_Triangulation)& tri,
                     const TopLoc_Location& loc) {
    if (!poly->HasParameters())
        throw Error("tessellate", "Edge" + std::to_string(e) + " has a discretisation without parameters");
    TopoDS_Vertex v1, v2;
    TopExp::Vertices(edge, v1, v2);
    const int id1 = shape.vertices.FindIndex(v1) - 1, id2 = shape.vertices.FindIndex(v2) - 1;
    const auto& pts = b.surface.points;
    const int m = poly->NbNodes();
    std::vector<int>& ids = b.edge_nodes[size_t(e)];
    std::vector<double>& params = b.edge_params[size_t(e)];
    ids.resize(size_t(m));
    params.resize(size_t(m));
    for (int j = 0; j < m; ++j) {
        const Eigen::Vector3d p = node(tri, poly->Node(j + 1), loc);
        params[size_t(j)] = poly->Parameter(j + 1);
        if (BRep_Tool::Degenerated(edge)) ids[size_t(j)] = id1;
        else if (j == 0 || j == m - 1)
            ids[size_t(j)] = (p - pts[size_t(id1)]).norm() <= (p - pts[size_t(id2)]).norm() ? id1 : id2;
        else ids[size_t(j)] = b.add(p);
    }
    if (m >= 2 && ids.front() == ids.back() && id1 != id2)  // both ends matched one vertex
        ids.back() = ids.front() == id1 ? id2 : id1;
    if (BRep_Tool::Degenerated(edge)) return;
    for (int j = 0; j + 1 < m; ++j) {
        const int a = ids[size_t(j)], c = ids[size_t(j + 1)];
        const double ta = params[size_t(j)], tc = params[size_t(j + 1)];
        if (a != c) b.surface.curve_edges[edge_key(a, c, kAnyIdStride)] = {e, a < c ? ta : tc, a < c ? tc : ta};
    }
}

// Local node -> point id for the nodes of `face` lying on its edges.
void map_edge_nodes(Builder& b, const BrepModel::Shape& shape, const TopoDS_Face& face, int f,
                    const Handle(Poly_Triangulation)& tri, const TopLoc_Location& loc, std::vector<int>& local) {
    const auto& pts = b.surface.points;
    for (TopExp_Explorer it(face, TopAbs_EDGE); it.More(); it.Next()) {
        const TopoDS_Edge edge = TopoDS::Edge(it.Current());
        const int e = shape.edges.FindIndex(edge);
        const Handle(Poly_PolygonOnTriangulation) poly = BRep_Tool::PolygonOnTriangulation(edge, tri, loc);
        if (poly.IsNull())
            throw Error("tessellate", "Edge" + std::to_string(e) + " of Face" + std::to_string(f) +
                                          " has no discretisation; the face may be invalid");
        if (b.edge_nodes[size_t(e)].empty()) discretise_edge(b, shape, edge, e, poly, tri, loc);
        const std::vector<int>& ids = b.edge_nodes[size_t(e)];
        const int m = poly->NbNodes();
        if (m != int(ids.size()))
            throw Error("tessellate", "Edge" + std::to_string(e) + " is discretised differently in Face" +
                                          std::to_string(f) + "; the shape is not watertight");
        bool reversed = false;  // polygons of one edge may run in opposite directions
        if (m >= 3) {
            const Eigen::Vector3d p = node(tri, poly->Node(2), loc);
            reversed = (p - pts[size_t(ids[size_t(m - 2)])]).norm() < (p - pts[size_t(ids[1])]).norm();
        } else if (m == 2 && ids[0] != ids[1]) {
            const Eigen::Vector3d p = node(tri, poly->Node(1), loc);
            reversed = (p - pts[size_t(ids[1])]).norm() < (p - pts[size_t(ids[0])]).norm();
        }
        for (int j = 0; j < m; ++j) local[size_t(poly->Node(j + 1))] = ids[size_t(reversed ? m - 1 - j : j)];
    }
}

void add_face(Builder& b, const BrepModel::Shape& shape, const TopoDS_Face& face, int f) {
    TopLoc_Location loc;
    const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(face, loc);
    if (tri.IsNull() || tri->NbTriangles() == 0 || !tri->HasUVNodes())
        throw Error("tessellate", "Face" + std::to_string(f) + " could not be triangulated; check the shape");
    std::vector<int> local(size_t(tri->NbNodes()) + 1, -1);
    map_edge_nodes(b, shape, face, f, tri, loc, local);
    for (int i = 1; i <= tri->NbNodes(); ++i)
        if (local[size_t(i)] < 0) local[size_t(i)] = b.add(node(tri, i, loc));
    const bool reversed = face.Orientation() == TopAbs_REVERSED;
    for (int t = 1; t <= tri->NbTriangles(); ++t) {
        int n[3];
        tri->Triangle(t).Get(n[0], n[1], n[2]);
        if (reversed) std::swap(n[1], n[2]);
        TaggedSurface::Triangle out;
        out.face = f;
        for (size_t k = 0; k < 3; ++k) {
            out.v[k] = local[size_t(n[k])];
            const gp_Pnt2d uv = tri->UVNode(n[k]);
            out.uv[k] = Eigen::Vector2d(uv.X(), uv.Y());
        }
        if (out.v[0] == out.v[1] || out.v[1] == out.v[2] || out.v[0] == out.v[2]) continue;  // at a degenerate edge
        b.surface.triangles.push_back(out);
    }
}

// Exact geometry for the refinement, on the copy's faces and edges.
class Geometry {
public:
    Geometry(const BrepModel::Shape& shape, const TopoDS_Shape& solid) : shape_(shape), solid_(solid) {
        for (int f = 1; f <= shape.faces.Extent(); ++f) {
            surfaces_.emplace_back(TopoDS::Face(shape.faces(f)));
            normals_.emplace_back(oriented_face(f));
            projectors_.push_back(new ShapeAnalysis_Surface(BRep_Tool::Surface(TopoDS::Face(shape.faces(f)))));
        }
        for (int e = 1; e <= shape.edges.Extent(); ++e) curves_.emplace_back(TopoDS::Edge(shape.edges(e)));
    }
    SurfaceEvaluator evaluator() {
        SurfaceEvaluator eval;
        eval.on_face = [this](int f, const Eigen::Vector2d& uv) {
            return to_eigen(surfaces_[size_t(f - 1)].Value(uv.x(), uv.y()));
        };
        eval.on_edge = [this](int e, double t) { return to_eigen(curves_[size_t(e - 1)].Value(t)); };
        eval.normal = [this](int f, const Eigen::Vector2d& uv) {
            gp_Pnt p;
            gp_Vec n;
            normals_[size_t(f - 1)].Normal(uv.x(), uv.y(), p, n);
            const double len = n.Magnitude();
            return len > 1e-12 ? Eigen::Vector3d(n.X() / len, n.Y() / len, n.Z() / len) : Eigen::Vector3d::Zero();
        };
        eval.edge_uv = [this](int e, int f, double t, const Eigen::Vector2d& near) {
            Eigen::Vector2d best = near;
            double best_d = 1e300;
            const BRepAdaptor_Surface& surface = surfaces_[size_t(f - 1)];
            for (const auto& pcurve : pcurves(e, f)) {
                const gp_Pnt2d p = pcurve.Value(t);
                Eigen::Vector2d uv(p.X(), p.Y());
                // A pcurve may run past the period; the triangulation's parameters do not.
                if (surface.IsUPeriodic()) uv.x() += surface.UPeriod() * std::round((near.x() - uv.x()) / surface.UPeriod());
                if (surface.IsVPeriodic()) uv.y() += surface.VPeriod() * std::round((near.y() - uv.y()) / surface.VPeriod());
                if ((uv - near).norm() < best_d) best_d = (uv - near).norm(), best = uv;
            }
            return best;
        };
        eval.project = [this](int f, const Eigen::Vector3d& p, const Eigen::Vector2d& near) {
            const gp_Pnt2d uv = projectors_[size_t(f - 1)]->NextValueOfUV(gp_Pnt2d(near.x(), near.y()),
                                                                         gp_Pnt(p.x(), p.y(), p.z()), kProjectionTol);
            return Eigen::Vector2d(uv.X(), uv.Y());
        };
        return eval;
    }

private:
    static constexpr double kProjectionTol = 1e-9;  // model units: the exact nearest point

    static Eigen::Vector3d to_eigen(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }

    // The edge's pcurves on the face: two for a seam.
    const std::vector<BRepAdaptor_Curve2d>& pcurves(int e, int f) {
        auto& list = pcurves_[{e, f}];
        if (list.empty()) {
            const TopoDS_Face face = TopoDS::Face(shape_.faces(f));
            for (TopExp_Explorer it(face, TopAbs_EDGE); it.More(); it.Next())
                if (it.Current().IsSame(shape_.edges(e))) list.emplace_back(TopoDS::Edge(it.Current()), face);
        }
        return list;
    }

    // The face as it occurs in the solid, so that BRepGProp_Face's normal points outward.
    TopoDS_Face oriented_face(int f) const {
        for (TopExp_Explorer it(solid_, TopAbs_FACE); it.More(); it.Next())
            if (it.Current().IsSame(shape_.faces(f))) return TopoDS::Face(it.Current());
        return TopoDS::Face(shape_.faces(f));
    }

    const BrepModel::Shape& shape_;
    TopoDS_Shape solid_;
    std::vector<BRepAdaptor_Surface> surfaces_;
    std::vector<BRepGProp_Face> normals_;
    std::vector<Handle(ShapeAnalysis_Surface)> projectors_;  // located surfaces, like surfaces_
    std::vector<BRepAdaptor_Curve> curves_;
    std::map<std::pair<int, int>, std::vector<BRepAdaptor_Curve2d>> pcurves_;
};

SurfaceMesh to_surface_mesh(const TaggedSurface& ts, const FeatureSet& features, int num_vertices) {
    SurfaceMesh s;
    s.points.resize(Eigen::Index(ts.points.size()), 3);
    for (size_t i = 0; i < ts.points.size(); ++i) s.points.row(Eigen::Index(i)) = ts.points[i].transpose();
    s.triangles.resize(Eigen::Index(ts.triangles.size()), 3);
    s.face_tags.resize(Eigen::Index(ts.triangles.size()));
    for (size_t t = 0; t < ts.triangles.size(); ++t) {
        for (size_t k = 0; k < 3; ++k) s.triangles(Eigen::Index(t), Eigen::Index(k)) = ts.triangles[t].v[k];
        s.face_tags(Eigen::Index(t)) = ts.triangles[t].face;
    }
    std::vector<std::array<int, 3>> segments;  // (a, b, edge), sorted for determinism
    for (const auto& [key, ce] : ts.curve_edges) {
        const auto [a, b] = key_ids(key, kAnyIdStride);
        if (features.valence_of(ce.edge) > 0) segments.push_back({a, b, ce.edge});
    }
    std::sort(segments.begin(), segments.end());
    s.feature_segments.resize(Eigen::Index(segments.size()), 2);
    s.segment_tags.resize(Eigen::Index(segments.size()));
    for (size_t i = 0; i < segments.size(); ++i) {
        s.feature_segments.row(Eigen::Index(i)) << segments[i][0], segments[i][1];
        s.segment_tags(Eigen::Index(i)) = segments[i][2];
    }
    s.corner_points = Eigen::VectorXi::LinSpaced(num_vertices, 0, num_vertices - 1);
    return s;
}

}  // namespace

double default_size(const BrepModel& model, int target_tets) {
    if (target_tets <= 0) throw Error("mesh", "target of " + std::to_string(target_tets) + " tets; give a positive number");
    return size_for_tets(model.volume, target_tets);
}

SurfaceMesh tessellate(const BrepModel& model, const FeatureSet& features, const MeshOptions& options) {
    FF_ASSERT(model.shape);
    const BrepModel::Shape& shape = *model.shape;
    if (options.size < 0) throw Error("mesh", "size " + std::to_string(options.size) + " is negative; give a positive edge length");
    const double h = options.size > 0 ? options.size : default_size(model, options.target_tets);
    check_memory(model.volume, h, options);
    return occt_call("tessellate", "triangulating the surface", [&] {
        // BRepMesh stores triangulations in the shape: work on a copy, the model stays untouched.
        BRepBuilderAPI_Copy copier(shape.solid, false, false);
        const TopoDS_Shape copy = copier.Shape();
        IMeshTools_Parameters params;
        params.Deflection = h / kDeflectionDivisor;
        params.Angle = kAngleRad;
        params.MinSize = 0.05 * h;
        params.InParallel = false;  // deterministic
        BRepMesh_IncrementalMesh mesher(copy, params);
        if (!mesher.IsDone()) throw Error("tessellate", "OCCT surface meshing failed; check the shape");

        BrepModel::Shape copied;  // the copy's sub-shapes, indexed like the model's
        for (int i = 1; i <= shape.faces.Extent(); ++i) copied.faces.Add(copier.ModifiedShape(shape.faces(i)));
        for (int i = 1; i <= shape.edges.Extent(); ++i) copied.edges.Add(copier.ModifiedShape(shape.edges(i)));
        for (int i = 1; i <= shape.vertices.Extent(); ++i)
            copied.vertices.Add(copier.ModifiedShape(shape.vertices(i)));

        Builder b;
        b.edge_nodes.resize(size_t(shape.edges.Extent()) + 1);
        b.edge_params.resize(size_t(shape.edges.Extent()) + 1);
        for (int i = 1; i <= copied.vertices.Extent(); ++i) {
            const gp_Pnt p = BRep_Tool::Pnt(TopoDS::Vertex(copied.vertices(i)));
            b.add(Eigen::Vector3d(p.X(), p.Y(), p.Z()));
        }
        // Faces as they occur in the solid, so that their orientation is the outward one.
        std::vector<bool> done(size_t(shape.faces.Extent()) + 1, false);
        for (TopExp_Explorer it(copy, TopAbs_FACE); it.More(); it.Next()) {
            const int f = copied.faces.FindIndex(it.Current());
            if (f <= 0 || done[size_t(f)]) continue;
            done[size_t(f)] = true;
            add_face(b, copied, TopoDS::Face(it.Current()), f);
        }
        for (int f = 1; f <= shape.faces.Extent(); ++f)
            if (!done[size_t(f)]) throw Error("tessellate", "Face" + std::to_string(f) + " is not part of the solid's shells");
        Geometry geometry(copied, copy);
        const double budget = 4.0 * estimate_tets(model.volume, h);  // surface points are far fewer
        std::vector<double> face_max(size_t(shape.faces.Extent()) + 1, 0);
        for (const auto& [face, size] : options.face_size) {
            if (face < 1 || face > shape.faces.Extent() || !(size > 0))
                throw Error("mesh", "size " + std::to_string(size) + " on Face" + std::to_string(face) +
                                        ": give a face of the part and a positive size");
            face_max[size_t(face)] = kMaxEdge * size;
        }
        refine_surface(b.surface, geometry.evaluator(), kMaxEdge * h, int(std::min(budget, 2e9)), face_max);
        return to_surface_mesh(b.surface, features, copied.vertices.Extent());
    });
}

}  // namespace framefix
