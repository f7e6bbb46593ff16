// Whether the solid itself self-intersects, by OCCT's own test (BOPAlgo_ArgumentAnalyzer in its
// self-interference mode, the test FreeCAD's "Check geometry" runs). BRepCheck_Analyzer does not
// look for faces crossing each other or themselves, so a lofted blade whose section loops passes it.
#include <algorithm>
#include <vector>

#include <BOPAlgo_ArgumentAnalyzer.hxx>
#include <BOPAlgo_CheckResult.hxx>
#include <TopTools_ListOfShape.hxx>

#include "framefix/brep/brep_model.h"
#include "framefix/brep/occt_error.h"
#include "framefix/brep/shape.h"
#include "framefix/core/bytes.h"
#include "framefix/core/isolation.h"

namespace framefix {
namespace {

// Generous: the test is quadratic in the faces' sub-shapes on large parts, and it only runs
// after the meshing found a self-intersection.
constexpr double kCheckTimeoutS = 120;

Eigen::VectorXi faulty_faces(const BrepModel& model) {
    const BrepModel::Shape& shape = *model.shape;
    BOPAlgo_ArgumentAnalyzer analyzer;
    analyzer.SetShape1(shape.solid);
    analyzer.SelfInterMode() = true;
    analyzer.ArgumentTypeMode() = false;
    analyzer.SmallEdgeMode() = false;
    analyzer.RebuildFaceMode() = false;
    analyzer.TangentMode() = false;
    analyzer.MergeVertexMode() = false;
    analyzer.MergeEdgeMode() = false;
    analyzer.ContinuityMode() = false;
    analyzer.CurveOnSurfaceMode() = false;
    analyzer.Perform();
    std::vector<int> faces;
    if (analyzer.HasFaulty())
        for (const BOPAlgo_CheckResult& result : analyzer.GetCheckResult()) {
            if (result.GetCheckStatus() != BOPAlgo_SelfIntersect) continue;
            for (const TopoDS_Shape& s : result.GetFaultyShapes1()) {
                const int f = shape.faces.FindIndex(s);
                if (f > 0) faces.push_back(f);
            }
        }
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    return Eigen::Map<const Eigen::VectorXi>(faces.data(), Eigen::Index(faces.size()));
}

}  // namespace

Eigen::VectorXi self_intersecting_faces(const BrepModel& model) {
    FF_ASSERT(model.shape);
    const IsolatedTask task{"mesh", "OpenCASCADE's self-intersection check", "check the solid in the CAD tool",
                            kCheckTimeoutS};
    const std::string bytes = run_isolated(task, [&] {
        ByteWriter w;
        w.matrix(occt_call("mesh", "checking the solid for self-intersections", [&] { return faulty_faces(model); }));
        return w.take();
    });
    ByteReader r(bytes);
    Eigen::VectorXi faces;
    r.matrix(faces);
    return faces;
}

}  // namespace framefix
