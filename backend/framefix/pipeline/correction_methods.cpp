#include "framefix/pipeline/correction_methods.h"

#include <algorithm>
#include <chrono>
#include <map>

#include "framefix/core/error.h"
#include "framefix/pipeline/fillet_plan.h"
#include "framefix/mesh/boundary_surface.h"
#include "framefix/pipeline/mesh_attempts.h"
#include "framefix/tetgen/tetrahedralize.h"

namespace framefix {
namespace {

// Boundary snapping: the ends of each 3-5 curve are pulled onto the boundary and the frames
// along the boundary path between them are set so that the curve lies on the boundary.
bool apply_snap(CorrectionContext& c) {
    // A graph whose only defects are invalid nodes has no 3-5 curve to start from: snap the nodes.
    SnapOptions so = c.options.snap;
    if (c.graph.summary.curves_3_5 == 0 && c.graph.summary.invalid_nodes > 0) so.snap_invalid_nodes = true;
    c.record.snap = snap_three_five_curves(c.mesh.tets, c.mesh.topology, c.mesh.features, c.field.constraints,
                                           c.field.frames, c.graph, so);
    if (c.record.snap.snapped_curve_ids.empty()) return false;
    c.field.constraints = c.record.snap.constraints;
    return true;
}

// With rims, a fillet whose room kept its radius below one edge length h is meshed at r / this
// (the three edges per radius that r = 3 h gives where there is room), but no finer than
// kFinestFilletSize h. Only with rims: on concave-only fillets it cost more graphs than it
// made valid (docs/algorithms.md#re-analysis).
constexpr double kEdgesPerFilletRadius = 3;
constexpr double kFinestFilletSize = 0.5;

// Features and tets of a new solid at the size h of the mesh it replaces; faces in face_size
// (the fillet surfaces) get their smaller sizes.
MeshStage remesh(const BrepModel& model, const RunOptions& options, double h, std::map<int, double> face_size = {}) {
    MeshStage m;
    m.features = classify_features(model, options.features);
    MeshOptions mo = options.mesh;
    mo.size = h;
    mo.face_size = std::move(face_size);
    if (mo.threads == 0) mo.threads = options.threads;
    BrepMeshing meshing = mesh_brep(model, m.features, mo);
    m.tets = std::move(meshing.tets);
    m.attempts = std::move(meshing.attempts);
    m.narrow_faces = meshing.narrow_faces;
    m.mesher = mesher_name(meshing.mesher);
    m.topology = build_topology(m.tets);
    return m;
}

// Fillet insertion on the B-rep (paper section 4.3): the concave edges next to each 3-5 curve are
// filleted by OCCT, and the filleted solid is meshed again at the same size.
bool apply_fillet(CorrectionContext& c) {
    if (!c.model)
        throw Error("correct", "method 'fillet' changes the B-rep and this input is a tet mesh; give the CAD part "
                               "(.step, .brep, .iges) or use --method snap");
    const auto t0 = std::chrono::steady_clock::now();
    const auto since = [](auto t) { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count(); };
    const FilletPlan plan = plan_fillets(*c.model, c.mesh.features, c.graph, c.graph.h_mean, c.options.fillet);
    c.record.notes = plan.notes;
    if (plan.requests.empty()) return false;
    FilletResult f = fillet_edges(*c.model, plan.requests);
    c.record.fillets = f.fillets;
    c.record.fillet_how = f.how;
    c.record.fillet_seconds = since(t0);
    if (std::none_of(f.fillets.begin(), f.fillets.end(), [](const FilletOutcome& o) { return o.done; })) return false;
    c.record.filleted = std::make_shared<const BrepModel>(std::move(f.model));
    const double h = c.mesh.tets.size;
    std::map<int, double> fine;
    for (const auto& [face, radius] : f.fillet_faces)
        if (c.options.fillet.rims && radius < h) fine[face] = std::max(radius / kEdgesPerFilletRadius, kFinestFilletSize * h);
    c.record.fine_fillet_faces = int(fine.size());
    c.mesh = remesh(*c.record.filleted, c.options, h, std::move(fine));
    c.record.remesh_seconds = since(t0) - c.record.fillet_seconds;
    c.field.constraints = boundary_constraints(c.mesh.tets, c.mesh.features);
    c.record.remeshed = true;
    return true;
}

ExtrusionOptions extrusion_options(const RunOptions& o) {
    ExtrusionOptions e;
    e.threads = o.threads;
    return e;
}

// Both extrusions: the planned points are inserted into a new mesh of the same boundary, which
// carries the internal constraints. A TetGen failure is a reported failure, not an error.
bool apply_extrusion(CorrectionContext& c, ExtrusionPlan plan) {
    const auto t0 = std::chrono::steady_clock::now();
    c.record.extrusion = std::move(plan);
    ExtrusionPlan& p = c.record.extrusion;
    if (p.points.rows() == 0) return false;
    MeshOptions mo = c.options.mesh;
    mo.size = c.mesh.tets.size;
    Points all(p.points.rows() + p.ring_points.rows(), 3);
    all << p.points, p.ring_points;
    // TetGen's boundary recovery can crash with points near the boundary: then let it split
    // boundary triangles (the pieces keep their tags) as the first meshing does. Node extrusion
    // lets it from the start: the forced curves' ends on the boundary need the finer triangles.
    const SurfaceMesh surface = boundary_surface(c.mesh.tets).surface;
    TetgenRun run = try_tetrahedralize(surface, mo, !p.refine_boundary, all);
    if (run.status != TetgenStatus::meshed && !p.refine_boundary) run = try_tetrahedralize(surface, mo, false, all);
    if (run.status != TetgenStatus::meshed) {
        p.failures.push_back({"mesh", "TetGen could not insert the streamline points: " + run.message});
        return false;
    }
    Constraints constraints = boundary_constraints(run.mesh, c.mesh.features);
    c.record.constrained_points = add_internal_constraints(run.mesh, p, constraints, extrusion_options(c.options));
    c.record.extrusion_seconds = p.seconds;
    c.record.remesh_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (c.record.constrained_points == 0) {  // the run keeps its mesh and field
        p.failures.push_back({"mesh", "no inserted point is a free vertex of the new mesh: nothing to constrain"});
        return false;
    }
    c.mesh.tets = std::move(run.mesh);
    c.mesh.topology = build_topology(c.mesh.tets);
    c.field.constraints = std::move(constraints);
    c.record.remeshed = true;
    return true;
}

bool apply_extrude_curves(CorrectionContext& c) {
    return apply_extrusion(c, plan_curve_extrusion(c.mesh.tets, c.mesh.topology, c.mesh.features, c.field.frames, c.graph,
                                                   extrusion_options(c.options)));
}

bool apply_extrude_nodes(CorrectionContext& c) {
    return apply_extrusion(c, plan_node_extrusion(c.mesh.tets, c.mesh.topology, c.field.frames, c.graph, extrusion_options(c.options)));
}

std::string names() {
    std::string s;
    const auto& all = correction_methods();
    for (size_t i = 0; i < all.size(); ++i) s += (i ? (i + 1 == all.size() ? " or " : ", ") : "") + all[i].name;
    return s;
}

}  // namespace

const std::vector<CorrectionMethod>& correction_methods() {
    static const std::vector<CorrectionMethod> methods = {
        {"auto", "try the methods, cheapest first and the fillet last, and keep the best (never worse than the input)",
         true, nullptr, true},
        {"snap", "snap 3-5 curves onto the boundary (the paper's recommendation)", true, &apply_snap, true},
        {"fillet", "insert fillets on the B-rep along the concave feature curves that cause 3-5 curves", true, &apply_fillet, true},
        {"extrude-curves", "extrude the concave feature curves into the volume along the field's stable direction", true, &apply_extrude_curves, true},
        {"extrude-nodes", "extrude the ends of the 3-5 curves into the volume along streamlines of the field", true, &apply_extrude_nodes, true},
    };
    return methods;
}

const CorrectionMethod& find_correction_method(const std::string& name) {
    for (const auto& m : correction_methods()) {
        if (m.name != name) continue;
        if (!m.available)
            throw Error("correct", "method '" + name + "' is not available yet; use --method " + correction_methods()[0].name);
        return m;
    }
    throw Error("correct", "unknown method '" + name + "'; use " + names());
}

}  // namespace framefix
