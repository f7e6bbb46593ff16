#include "fixtures.h"

#include <sstream>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>

namespace framefix::test {
namespace {

BrepModel from_shape(const TopoDS_Shape& shape) {
    std::ostringstream out;
    BRepTools::Write(shape, out);
    return load_brep_string(out.str());
}

}  // namespace

std::string sample(const std::string& name) { return std::string(FRAMEFIX_SAMPLES_DIR) + "/" + name + ".step"; }

std::string bad_input(const std::string& name) {
    return std::string(FRAMEFIX_SAMPLES_DIR) + "/../tests/data/" + name;
}

BrepModel box(double x, double y, double z) { return from_shape(BRepPrimAPI_MakeBox(x, y, z).Shape()); }

BrepModel box_with_blind_hole() {
    const TopoDS_Shape block = BRepPrimAPI_MakeBox(1, 1, 1).Shape();
    const TopoDS_Shape hole = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0.5, 0.5, 0.5), gp_Dir(0, 0, 1)), 0.25, 1).Shape();
    return from_shape(BRepAlgoAPI_Cut(block, hole).Shape());
}

BrepModel box_with_fillet() {
    const TopoDS_Shape block = BRepPrimAPI_MakeBox(1, 1, 1).Shape();
    BRepFilletAPI_MakeFillet fillet(block);
    for (TopExp_Explorer it(block, TopAbs_EDGE); it.More(); it.Next()) {
        const TopoDS_Edge edge = TopoDS::Edge(it.Current());
        const gp_Pnt a = BRep_Tool::Pnt(TopExp::FirstVertex(edge)), b = BRep_Tool::Pnt(TopExp::LastVertex(edge));
        if (a.X() == 0 && a.Y() == 0 && b.X() == 0 && b.Y() == 0) fillet.Add(0.2, edge);  // the edge on the z axis
    }
    return from_shape(fillet.Shape());
}

}  // namespace framefix::test
