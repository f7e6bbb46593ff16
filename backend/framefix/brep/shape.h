#pragma once
// What BrepModel::Shape hides: the solid and its indexed sub-shapes. Index i of a map
// (1-based, TopExp::MapShapes order) is FreeCAD's Face<i> / Edge<i> / Vertex<i>.
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Shape.hxx>

#include "framefix/brep/brep_model.h"

namespace framefix {

struct BrepModel::Shape {
    TopoDS_Shape solid;                  // a TopoDS_Solid, valid, positive volume
    TopTools_IndexedMapOfShape faces;    // TopExp::MapShapes(solid, TopAbs_FACE)
    TopTools_IndexedMapOfShape edges;    // TopExp::MapShapes(solid, TopAbs_EDGE)
    TopTools_IndexedMapOfShape vertices; // TopExp::MapShapes(solid, TopAbs_VERTEX)
};

// Checks that `shape` is (or holds) exactly one valid solid and builds the model around it;
// `source` names the input in messages (a path or "BREP string").
BrepModel make_model(const TopoDS_Shape& shape, const std::string& source, const std::string& path,
                     const std::string& kind);

}  // namespace framefix
