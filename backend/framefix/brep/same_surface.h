#pragma once
// Whether two faces lie on one underlying surface: an edge between them is an imprinted curve
// (a split face), not a crease or a tangent junction of two different surfaces.
#include <TopoDS_Face.hxx>

namespace framefix {

// Same geometry object, or analytic surfaces (plane, cylinder, cone, sphere, torus) that
// coincide within `tolerance` (model units).
bool same_surface(const TopoDS_Face& a, const TopoDS_Face& b, double tolerance);

}  // namespace framefix
