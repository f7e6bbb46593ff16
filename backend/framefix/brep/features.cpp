// Feature curves of a B-rep solid: the dihedral angle inside the solid along every edge.
//
// At a point P of edge E shared by faces F1, F2: N_i is F_i's outward normal, t_i the tangent of E
// as oriented in F_i (the face lies on the left of t_i seen from N_i), D_i = N_i x t_i points
// from E into F_i. In the plane normal to E, the solid fills the wedge turning from D1 towards
// -N1 until D2: theta = atan2(D2 . -N1, D2 . D1) in [0, 360) degrees.
#include <algorithm>
#include <cmath>
#include <vector>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Curve2d.hxx>
#include <BRepGProp_Face.hxx>
#include <BRep_Tool.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>
#include <gp_Pnt2d.hxx>
#include <gp_Vec.hxx>

#include "framefix/brep/occt_error.h"
#include "framefix/brep/same_surface.h"
#include "framefix/brep/shape.h"

namespace framefix {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Faces around an edge, each once (a seam edge lists its face twice).
std::vector<TopoDS_Face> distinct_faces(const TopTools_ListOfShape& ancestors) {
    std::vector<TopoDS_Face> faces;
    for (const TopoDS_Shape& s : ancestors) {
        const bool seen = std::any_of(faces.begin(), faces.end(), [&](const TopoDS_Face& f) { return f.IsSame(s); });
        if (!seen) faces.push_back(TopoDS::Face(s));
    }
    return faces;
}

// The edge as it occurs in the face's wires (orientation composed with the face's).
TopoDS_Edge edge_in_face(const TopoDS_Edge& edge, const TopoDS_Face& face) {
    for (TopExp_Explorer it(face, TopAbs_EDGE); it.More(); it.Next())
        if (it.Current().IsSame(edge)) return TopoDS::Edge(it.Current());
    return edge;
}

// Outward unit normal of `face` at `edge`'s parameter t and unit direction into the face;
// false where the surface normal is undefined (poles, apexes).
bool side_frame(const TopoDS_Edge& edge, const TopoDS_Face& face, double t, const gp_Vec& tangent,
                gp_Vec& normal, gp_Vec& inward) {
    const TopoDS_Edge oriented = edge_in_face(edge, face);
    BRepAdaptor_Curve2d pcurve(oriented, face);
    const gp_Pnt2d uv = pcurve.Value(t);
    BRepGProp_Face surface(face);
    gp_Pnt point;
    surface.Normal(uv.X(), uv.Y(), point, normal);
    if (normal.Magnitude() < 1e-12) return false;
    normal.Normalize();
    const gp_Vec along = oriented.Orientation() == TopAbs_REVERSED ? -tangent : tangent;
    inward = normal.Crossed(along);
    if (inward.Magnitude() < 1e-9) return false;
    inward.Normalize();
    return true;
}

double dihedral_deg(const gp_Vec& n1, const gp_Vec& d1, const gp_Vec& d2) {
    double a = std::atan2(-d2.Dot(n1), d2.Dot(d1)) * 180.0 / kPi;
    return a < 0 ? a + 360.0 : a;
}

int valence_class(double theta, double tangent_deg) {
    if (std::abs(theta - 180.0) < tangent_deg) return 0;
    return std::clamp(int(std::lround(theta / 90.0)), 1, 4);
}

EdgeFeature classify_edge(const TopoDS_Edge& edge, const std::vector<TopoDS_Face>& faces,
                          const FeatureOptions& options, double tolerance) {
    EdgeFeature f;
    if (BRep_Tool::Degenerated(edge)) {
        f.reason = "degenerate";
        return f;
    }
    BRepAdaptor_Curve curve(edge);
    f.length = GCPnts_AbscissaPoint::Length(curve);
    if (faces.size() == 1) {
        f.reason = "seam";
        return f;
    }
    if (faces.size() != 2) {
        f.reason = "non-manifold";
        return f;
    }
    const bool imprint = same_surface(faces[0], faces[1], tolerance);
    const int n = std::max(1, options.samples_per_edge);
    std::vector<double> angles;
    for (int k = 0; k < n; ++k) {
        const double t = curve.FirstParameter() + (k + 0.5) / n * (curve.LastParameter() - curve.FirstParameter());
        gp_Pnt p;
        gp_Vec tangent;
        curve.D1(t, p, tangent);
        if (tangent.Magnitude() < 1e-12) continue;
        tangent.Normalize();
        gp_Vec n1, d1, n2, d2;
        if (!side_frame(edge, faces[0], t, tangent, n1, d1) || !side_frame(edge, faces[1], t, tangent, n2, d2))
            continue;
        angles.push_back(dihedral_deg(n1, d1, d2));
    }
    if (angles.empty()) {
        f.reason = "undefined normal";
        return f;
    }
    f.angle_min_deg = *std::min_element(angles.begin(), angles.end());
    f.angle_max_deg = *std::max_element(angles.begin(), angles.end());
    if (imprint) {
        f.valence = 2;
        return f;
    }
    int votes[5] = {0, 0, 0, 0, 0};
    double mean = 0;
    for (double a : angles) {
        votes[valence_class(a, options.tangent_angle_deg)] += 1;
        mean += a / double(angles.size());
    }
    int best = valence_class(mean, options.tangent_angle_deg);
    for (int k = 0; k < 5; ++k)
        if (votes[k] > votes[best]) best = k;
    f.valence_varies = std::count_if(votes, votes + 5, [](int v) { return v > 0; }) > 1;
    f.valence = best;
    if (best == 0) f.reason = "tangent";
    return f;
}

}  // namespace

FeatureSet classify_features(const BrepModel& model, const FeatureOptions& options) {
    FF_ASSERT(model.shape);
    const BrepModel::Shape& shape = *model.shape;
    return occt_call("features", "classifying edges", [&] {
        TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
        TopExp::MapShapesAndAncestors(shape.solid, TopAbs_EDGE, TopAbs_FACE, edge_faces);
        const double tolerance = 1e-6 * (model.bbox_max - model.bbox_min).norm();
        FeatureSet set;
        for (int i = 1; i <= shape.edges.Extent(); ++i) {
            const TopoDS_Edge edge = TopoDS::Edge(shape.edges(i));
            const int j = edge_faces.FindIndex(edge);
            const std::vector<TopoDS_Face> faces =
                j > 0 ? distinct_faces(edge_faces(j)) : std::vector<TopoDS_Face>{};
            EdgeFeature f = classify_edge(edge, faces, options, tolerance);
            f.edge = i;
            for (const TopoDS_Face& face : faces) f.faces.push_back(shape.faces.FindIndex(face));
            TopoDS_Vertex first, last;
            TopExp::Vertices(edge, first, last);
            for (const TopoDS_Vertex& v : {first, last})
                if (!v.IsNull() && (f.vertices.empty() || f.vertices[0] != shape.vertices.FindIndex(v)))
                    f.vertices.push_back(shape.vertices.FindIndex(v));
            set.edges.push_back(f);
        }
        return set;
    });
}

}  // namespace framefix
