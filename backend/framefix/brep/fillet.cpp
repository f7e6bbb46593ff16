#include "framefix/brep/fillet.h"

#include <cmath>
#include <memory>
#include <sstream>

#include <BRepAdaptor_Curve.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepGProp.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Precision.hxx>
#include <GProp_GProps.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>

#include "framefix/brep/occt_error.h"
#include "framefix/brep/shape.h"
#include "framefix/core/bytes.h"
#include "framefix/core/isolation.h"

namespace framefix {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kSameEdgeTolerance = 10;  // edge tolerances: how far one edge's middle may lie from its copy

struct Step {
    TopoDS_Shape shape;
    std::string failure;  // empty when the fillets were made and the result checked
};

double volume_of(const TopoDS_Shape& s) {
    GProp_GProps props;
    BRepGProp::VolumeProperties(s, props);
    return props.Mass();
}

double length_of(const TopoDS_Shape& edge) {
    GProp_GProps props;
    BRepGProp::LinearProperties(edge, props);
    return props.Mass();
}

int solids_in(const TopoDS_Shape& s) {
    int n = 0;
    for (TopExp_Explorer it(s, TopAbs_SOLID); it.More(); it.Next()) ++n;
    return n;
}

// What a fillet of these edges should add (concave edges) and remove (convex ones), both >= 0.
std::pair<double, double> expected_change(const std::vector<TopoDS_Shape>& edges, const std::vector<FilletRequest>& req,
                                          const std::vector<double>& radius) {
    double added = 0, removed = 0;
    for (size_t i = 0; i < edges.size(); ++i) {
        const double v = fillet_section_area(radius[i], req[i].theta_deg) * length_of(edges[i]);
        (v > 0 ? added : removed) += std::abs(v);
    }
    return {added, removed};
}

// Each part of the change may be off by volume_factor either way; concave and convex fillets of
// one groove cancel, so only the interval of the net change can be checked.
bool volume_fits(double dv, std::pair<double, double> want, double k) {
    const auto [added, removed] = want;
    return dv >= added / k - removed * k && dv <= added * k - removed / k;
}

// One BRepFilletAPI_MakeFillet over `edges` with `radius`, checked: valid, one solid, volume
// change within volume_factor of the expectation. `made` receives the builder for the history.
Step fillet_once(const TopoDS_Shape& solid, const std::vector<TopoDS_Shape>& edges, const std::vector<FilletRequest>& req,
                 const std::vector<double>& radius, const FilletOptions& o, std::unique_ptr<BRepFilletAPI_MakeFillet>& mk) {
    Step step;
    try {
        mk = std::make_unique<BRepFilletAPI_MakeFillet>(solid);
        for (size_t i = 0; i < edges.size(); ++i) mk->Add(radius[i], TopoDS::Edge(edges[i]));
        mk->Build();
        if (!mk->IsDone()) return {{}, "OCCT could not build the fillet surface (BRepFilletAPI_MakeFillet failed)"};
        step.shape = mk->Shape();
    } catch (const Standard_Failure& f) {
        return {{}, "OCCT raised " + occt_message(f) + " while filleting"};
    }
    if (!BRepCheck_Analyzer(step.shape).IsValid()) return {{}, "the filleted solid is not valid (BRepCheck_Analyzer)"};
    if (solids_in(step.shape) != 1)
        return {{}, "the fillet gave " + std::to_string(solids_in(step.shape)) + " solids instead of one"};
    const double dv = volume_of(step.shape) - volume_of(solid);
    const std::pair<double, double> want = expected_change(edges, req, radius);
    if (!volume_fits(dv, want, o.volume_factor)) {
        std::ostringstream m;
        m << "the volume changed by " << dv << " where the fillet should change it by about "
          << want.first - want.second;
        return {{}, m.str()};
    }
    return step;
}

struct FaceOfFillet {
    TopoDS_Shape face;
    double radius = 0;
};

struct Plan {
    TopoDS_Shape shape;
    std::vector<FilletOutcome> out;
    std::string how;
    std::vector<FaceOfFillet> faces;  // the fillet surfaces made so far, in `shape`
};

// The faces a fillet made from `edges`, with their radii.
void add_new_faces(BRepFilletAPI_MakeFillet& mk, const std::vector<TopoDS_Shape>& edges, const std::vector<double>& radius,
                   std::vector<FaceOfFillet>& faces) {
    for (size_t i = 0; i < edges.size(); ++i)
        for (const TopoDS_Shape& f : mk.Generated(edges[i])) faces.push_back({f, radius[i]});
}

// Earlier fillet faces through a later fillet's history (a neighbouring fillet trims them).
void follow_faces(BRepFilletAPI_MakeFillet& mk, std::vector<FaceOfFillet>& faces) {
    std::vector<FaceOfFillet> next;
    for (const FaceOfFillet& f : faces) {
        if (!mk.Modified(f.face).IsEmpty()) {
            for (const TopoDS_Shape& g : mk.Modified(f.face)) next.push_back({g, f.radius});
        } else if (!mk.IsDeleted(f.face)) {
            next.push_back(f);
        }
    }
    faces = std::move(next);
}

std::vector<double> scaled(const std::vector<FilletRequest>& req, double s) {
    std::vector<double> r;
    for (const FilletRequest& q : req) r.push_back(q.radius * s);
    return r;
}

TopoDS_Shape middle(const TopoDS_Shape& edge) {
    const BRepAdaptor_Curve c(TopoDS::Edge(edge));
    return BRepBuilderAPI_MakeVertex(c.Value((c.FirstParameter() + c.LastParameter()) / 2));
}

double distance(const TopoDS_Shape& a, const TopoDS_Shape& b) {
    BRepExtrema_DistShapeShape d(a, b);
    return d.IsDone() && d.NbSolution() > 0 ? d.Value() : 1e300;
}

// The edge of `shape` on the same curve as `edge` (each one's middle lies on the other), or a
// null shape: a fillet's history calls some untouched edges deleted, as it rebuilds their faces.
TopoDS_Shape same_edge(const TopoDS_Shape& shape, const TopoDS_Shape& edge) {
    const double tol = kSameEdgeTolerance * std::max(BRep_Tool::Tolerance(TopoDS::Edge(edge)), Precision::Confusion());
    const TopoDS_Shape mid = middle(edge);
    for (TopExp_Explorer it(shape, TopAbs_EDGE); it.More(); it.Next())
        if (distance(mid, it.Current()) <= tol && distance(middle(it.Current()), edge) <= tol) return it.Current();
    return {};
}

// Follows the edges still to fillet through one fillet's history, or by their curve where the
// history says deleted.
void follow(BRepFilletAPI_MakeFillet& mk, size_t from, std::vector<TopoDS_Shape>& edges, std::vector<char>& lost) {
    for (size_t j = from; j < edges.size(); ++j) {
        if (lost[j]) continue;
        if (!mk.Modified(edges[j]).IsEmpty()) {
            edges[j] = mk.Modified(edges[j]).First();
        } else if (mk.IsDeleted(edges[j])) {
            const TopoDS_Shape e = same_edge(mk.Shape(), edges[j]);
            if (e.IsNull()) lost[j] = 1;
            else edges[j] = e;
        }
    }
}

Plan try_fillets(const BrepModel::Shape& shape, const std::vector<FilletRequest>& req, const FilletOptions& o) {
    Plan p;
    std::vector<TopoDS_Shape> edges;
    for (const FilletRequest& q : req) {
        edges.push_back(shape.edges(q.edge));
        p.out.push_back({q.edge, q.radius, false, ""});
    }
    std::string failure;
    for (double s : {1.0, o.retry_scale}) {
        std::unique_ptr<BRepFilletAPI_MakeFillet> mk;
        const Step step = fillet_once(shape.solid, edges, req, scaled(req, s), o, mk);
        if (!step.failure.empty()) continue;
        p.shape = step.shape;
        add_new_faces(*mk, edges, scaled(req, s), p.faces);
        for (size_t i = 0; i < req.size(); ++i) p.out[i].radius = req[i].radius * s, p.out[i].done = true;
        p.how = s == 1.0 ? "all at once" : "all at once, radii scaled by " + std::to_string(o.retry_scale);
        return p;
    }
    p.how = "edge by edge";
    p.shape = shape.solid;
    std::vector<char> lost(req.size(), 0);
    for (size_t i = 0; i < req.size(); ++i) {
        if (lost[i]) {
            p.out[i].reason = "an earlier fillet consumed the edge";
            continue;
        }
        for (double s : {1.0, o.retry_scale}) {
            std::unique_ptr<BRepFilletAPI_MakeFillet> mk;
            const Step step = fillet_once(p.shape, {edges[i]}, {req[i]}, {req[i].radius * s}, o, mk);
            if (!step.failure.empty()) {
                std::ostringstream m;
                m << step.failure << " at radius " << req[i].radius << " and " << req[i].radius * o.retry_scale
                  << " (larger than the faces next to the edge allow?)";
                p.out[i].reason = m.str();
                continue;
            }
            p.shape = step.shape;
            p.out[i] = {req[i].edge, req[i].radius * s, true, ""};
            follow_faces(*mk, p.faces);
            add_new_faces(*mk, {edges[i]}, {req[i].radius * s}, p.faces);
            follow(*mk, i + 1, edges, lost);
            break;
        }
    }
    return p;
}

void check_requests(const BrepModel& model, const std::vector<FilletRequest>& req) {
    for (const FilletRequest& q : req) {
        if (q.edge < 1 || q.edge > model.num_edges)
            throw Error("correct", "no Edge" + std::to_string(q.edge) + " to fillet: the solid has " +
                                       std::to_string(model.num_edges) + " edges");
        if (!(q.radius > 0))
            throw Error("correct", "fillet radius " + std::to_string(q.radius) + " on Edge" + std::to_string(q.edge) +
                                       "; give a radius > 0");
    }
}


}  // namespace

double fillet_room(const BrepModel& model, int edge) {
    FF_ASSERT(model.shape && edge >= 1 && edge <= model.num_edges);
    const BrepModel::Shape& s = *model.shape;
    return occt_call("correct", "measuring the room for a fillet on Edge" + std::to_string(edge), [&] {
        const TopoDS_Edge e = TopoDS::Edge(s.edges(edge));
        const TopoDS_Shape mid = middle(e);
        TopTools_IndexedDataMapOfShapeListOfShape faces_of;
        TopExp::MapShapesAndAncestors(s.solid, TopAbs_EDGE, TopAbs_FACE, faces_of);
        const TopTools_ListOfShape& next = faces_of.FindFromKey(e);
        double room = 1e300;
        for (int f = 1; f <= s.faces.Extent(); ++f) {
            bool holds = false;
            for (const TopoDS_Shape& g : next) holds |= g.IsSame(s.faces(f));
            if (!holds) room = std::min(room, distance(mid, s.faces(f)));
        }
        for (const TopoDS_Shape& face : next)
            for (TopExp_Explorer it(face, TopAbs_EDGE); it.More(); it.Next())
                if (!it.Current().IsSame(e)) room = std::min(room, distance(mid, it.Current()));
        return room;
    });
}

double fillet_section_area(double radius, double theta_deg) {
    // The two faces meet at angle beta = |180 - theta| away from flat; between them and the
    // tangent circle lies r^2 (cot(gamma / 2) - (pi - gamma) / 2), gamma = 180 - beta the
    // opening angle of the wedge the circle sits in.
    const double gamma = kPi - std::abs(kPi - theta_deg * kPi / 180);
    const double area = radius * radius * (1 / std::tan(gamma / 2) - (kPi - gamma) / 2);
    return theta_deg > 180 ? area : -area;
}

FilletResult fillet_edges(const BrepModel& model, const std::vector<FilletRequest>& requests, const FilletOptions& options) {
    FF_ASSERT(model.shape);
    check_requests(model, requests);
    FilletResult result;
    if (requests.empty()) {
        result.model = model;
        result.how = "nothing to fillet";
        return result;
    }
    const IsolatedTask task{"correct", "OpenCASCADE's fillet builder", "fillet the edges in the CAD tool", options.timeout_s};
    const std::string bytes = run_isolated(task, [&] {
        const Plan p = try_fillets(*model.shape, requests, options);
        ByteWriter w;
        w.text(p.how);
        for (const FilletOutcome& f : p.out) {
            w.value(f.radius);
            w.value<char>(f.done);
            w.text(f.reason);
        }
        TopTools_IndexedMapOfShape faces;
        TopExp::MapShapes(p.shape, TopAbs_FACE, faces);  // the order BRepTools::Read restores
        w.value<int>(int(p.faces.size()));
        for (const FaceOfFillet& f : p.faces) {
            w.value<int>(faces.FindIndex(f.face));
            w.value(f.radius);
        }
        std::ostringstream brep;
        BRepTools::Write(p.shape, brep);
        w.text(brep.str());
        return w.take();
    });
    ByteReader r(bytes);
    result.how = r.text();
    for (const FilletRequest& q : requests) {
        FilletOutcome f{q.edge, r.value<double>(), r.value<char>() != 0, ""};
        f.reason = r.text();
        result.fillets.push_back(f);
    }
    for (int i = 0, n = r.value<int>(); i < n; ++i) {
        const int face = r.value<int>();
        const double radius = r.value<double>();
        if (face > 0) result.fillet_faces.push_back({face, radius});
    }
    std::istringstream in(r.text());
    TopoDS_Shape shape;
    BRep_Builder builder;
    occt_call("correct", "reading the filleted solid", [&] { BRepTools::Read(shape, in, builder); });
    result.model = make_model(shape, "the filleted solid", "", "brep");
    result.volume_change = result.model.volume - model.volume;
    return result;
}

}  // namespace framefix
