// Geometric queries on a model, for tests and for corrections that snap to B-rep entities.
#include <BRepAdaptor_Curve.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepClass_FaceClassifier.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepGProp.hxx>
#include <BRep_Tool.hxx>
#include <ShapeAnalysis_Surface.hxx>
#include <GProp_GProps.hxx>
#include <TopoDS.hxx>

#include "framefix/brep/occt_error.h"
#include "framefix/brep/shape.h"

namespace framefix {
namespace {

// Distance from p to target, and the closest point of target in `closest` when given.
double distance_to(const TopoDS_Shape& target, const Eigen::Vector3d& p, Eigen::Vector3d* closest = nullptr) {
    return occt_call("brep", "distance query", [&] {
        const TopoDS_Vertex v = BRepBuilderAPI_MakeVertex(gp_Pnt(p.x(), p.y(), p.z()));
        BRepExtrema_DistShapeShape dist(v, target);
        if (!dist.IsDone() || dist.NbSolution() < 1) throw Error("brep", "distance query failed");
        if (closest) {
            const gp_Pnt q = dist.PointOnShape2(1);
            *closest = Eigen::Vector3d(q.X(), q.Y(), q.Z());
        }
        return dist.Value();
    });
}

}  // namespace

Points vertex_points(const BrepModel& model) {
    FF_ASSERT(model.shape);
    const auto& vertices = model.shape->vertices;
    Points points(vertices.Extent(), 3);
    for (int i = 1; i <= vertices.Extent(); ++i) {
        const gp_Pnt p = BRep_Tool::Pnt(TopoDS::Vertex(vertices(i)));
        points.row(i - 1) << p.X(), p.Y(), p.Z();
    }
    return points;
}

Points edge_points(const BrepModel& model, int edge, int n) {
    FF_ASSERT(model.shape && edge >= 1 && edge <= model.num_edges && n >= 2);
    return occt_call("brep", "sampling Edge" + std::to_string(edge), [&] {
        const BRepAdaptor_Curve curve(TopoDS::Edge(model.shape->edges(edge)));
        Points points(n, 3);
        for (int i = 0; i < n; ++i) {
            const double t = curve.FirstParameter() + (curve.LastParameter() - curve.FirstParameter()) * i / (n - 1);
            const gp_Pnt p = curve.Value(t);
            points.row(i) << p.X(), p.Y(), p.Z();
        }
        return points;
    });
}

double distance_to_edge(const BrepModel& model, int edge, const Eigen::Vector3d& p) {
    FF_ASSERT(model.shape);
    if (edge < 1 || edge > model.num_edges)
        throw Error("brep", "Edge" + std::to_string(edge) + " does not exist; the model has " +
                                std::to_string(model.num_edges) + " edges");
    return distance_to(model.shape->edges(edge), p);
}

Eigen::Vector3d closest_point_on_edge(const BrepModel& model, int edge, const Eigen::Vector3d& p) {
    FF_ASSERT(model.shape && edge >= 1 && edge <= model.num_edges);
    Eigen::Vector3d q;
    distance_to(model.shape->edges(edge), p, &q);
    return q;
}

double distance_to_face(const BrepModel& model, int face, const Eigen::Vector3d& p) {
    FF_ASSERT(model.shape);
    if (face < 1 || face > model.num_faces)
        throw Error("brep", "Face" + std::to_string(face) + " does not exist; the model has " +
                                std::to_string(model.num_faces) + " faces");
    return distance_to(model.shape->faces(face), p);
}

Eigen::Vector3d closest_point_on_face(const BrepModel& model, int face, const Eigen::Vector3d& p) {
    FF_ASSERT(model.shape && face >= 1 && face <= model.num_faces);
    return occt_call("brep", "projecting onto Face" + std::to_string(face), [&] {
        // The face's untrimmed surface first: the points projected lie on the face already
        // (within a mesh size), and it is much cheaper than BRepExtrema. A point beyond the trim
        // (a hex row next to a concave boundary curve, as on the dome's base circle at 0.7 x)
        // would land outside the face: then the trimmed face's closest point, on its edge.
        const TopoDS_Face& f = TopoDS::Face(model.shape->faces(face));
        ShapeAnalysis_Surface surface(BRep_Tool::Surface(f));
        const gp_Pnt q(p.x(), p.y(), p.z());
        const gp_Pnt2d uv = surface.ValueOfUV(q, Precision::Confusion());
        gp_Pnt r = surface.Value(uv);
        if (BRepClass_FaceClassifier(f, uv, BRep_Tool::Tolerance(f)).State() == TopAbs_OUT) {
            BRepExtrema_DistShapeShape d(BRepBuilderAPI_MakeVertex(q).Vertex(), f);
            if (d.IsDone() && d.NbSolution() > 0) r = d.PointOnShape2(1);
        }
        return Eigen::Vector3d(r.X(), r.Y(), r.Z());
    });
}

double face_width(const BrepModel& model, int face) {
    FF_ASSERT(model.shape && face >= 1 && face <= model.num_faces);
    return occt_call("brep", "measuring Face" + std::to_string(face), [&] {
        const TopoDS_Shape& f = model.shape->faces(face);
        GProp_GProps area, length;
        BRepGProp::SurfaceProperties(f, area);
        BRepGProp::LinearProperties(f, length);
        return length.Mass() > 0 ? 2 * area.Mass() / length.Mass() : 0.0;
    });
}

}  // namespace framefix
