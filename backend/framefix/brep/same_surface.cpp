#include "framefix/brep/same_surface.h"

#include <cmath>

#include <BRepAdaptor_Surface.hxx>
#include <BRep_Tool.hxx>
#include <gp_Ax1.hxx>
#include <gp_Lin.hxx>

namespace framefix {
namespace {

constexpr double kAngleTol = 1e-7;  // radians

bool same_axis_line(const gp_Ax1& a, const gp_Ax1& b, double tol) {
    if (!a.IsParallel(b, kAngleTol)) return false;
    return gp_Lin(a).Distance(b.Location()) < tol;
}

}  // namespace

bool same_surface(const TopoDS_Face& a, const TopoDS_Face& b, double tol) {
    TopLoc_Location la, lb;
    const Handle(Geom_Surface) ga = BRep_Tool::Surface(a, la);
    const Handle(Geom_Surface) gb = BRep_Tool::Surface(b, lb);
    if (!ga.IsNull() && ga == gb && la.IsEqual(lb)) return true;

    BRepAdaptor_Surface sa(a, false), sb(b, false);
    if (sa.GetType() != sb.GetType()) return false;
    switch (sa.GetType()) {
    case GeomAbs_Plane: {
        const gp_Pln pa = sa.Plane(), pb = sb.Plane();
        return pa.Axis().IsParallel(pb.Axis(), kAngleTol) && pa.Distance(pb.Location()) < tol;
    }
    case GeomAbs_Cylinder: {
        const gp_Cylinder ca = sa.Cylinder(), cb = sb.Cylinder();
        return std::abs(ca.Radius() - cb.Radius()) < tol && same_axis_line(ca.Axis(), cb.Axis(), tol);
    }
    case GeomAbs_Cone: {
        const gp_Cone ca = sa.Cone(), cb = sb.Cone();
        return ca.Apex().Distance(cb.Apex()) < tol && std::abs(ca.SemiAngle() - cb.SemiAngle()) < kAngleTol &&
               ca.Axis().Direction().IsEqual(cb.Axis().Direction(), kAngleTol);
    }
    case GeomAbs_Sphere: {
        const gp_Sphere ca = sa.Sphere(), cb = sb.Sphere();
        return std::abs(ca.Radius() - cb.Radius()) < tol && ca.Location().Distance(cb.Location()) < tol;
    }
    case GeomAbs_Torus: {
        const gp_Torus ca = sa.Torus(), cb = sb.Torus();
        return std::abs(ca.MajorRadius() - cb.MajorRadius()) < tol &&
               std::abs(ca.MinorRadius() - cb.MinorRadius()) < tol &&
               ca.Location().Distance(cb.Location()) < tol && ca.Axis().IsParallel(cb.Axis(), kAngleTol);
    }
    default:
        return false;
    }
}

}  // namespace framefix
