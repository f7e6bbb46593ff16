#include "framefix/pipeline/report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "framefix/core/error.h"
#include "framefix/singularities/edge_absorption.h"

namespace framefix {
namespace {

using json = nlohmann::json;

json point(const Eigen::Vector3d& p) { return json::array({p.x(), p.y(), p.z()}); }

json summary_json(const SingularitySummary& s) {
    return {{"curves", s.curves},         {"valence3", s.valence3}, {"valence5", s.valence5},
            {"curves_3_5", s.curves_3_5}, {"nodes", s.nodes},       {"invalid_nodes", s.invalid_nodes},
            {"meshable", s.meshable}};
}

json curve_json(const SingularCurve& c) {
    json pts = json::array();
    for (int i = 0; i < c.points.rows(); ++i) pts.push_back(point(c.points.row(i).transpose()));
    return {{"id", c.id},
            {"kind", to_string(c.kind)},
            {"length", c.length},
            {"ends", json::array({c.ends[0], c.ends[1]})},
            {"closed", c.closed},
            {"end_valences", json::array({c.end_valence[0], c.end_valence[1]})},
            {"triangles", c.faces.size()},
            {"transition", c.transition},
            {"stable_direction", point(c.stable_direction)},
            {"points", pts}};
}

json singularities_json(const SingularityGraph& g) {
    json curves = json::array(), nodes = json::array(), absorbed = json::array();
    for (const auto& c : g.curves) curves.push_back(curve_json(c));
    for (const auto& c : g.absorbed) absorbed.push_back(curve_json(c));
    for (const auto& n : g.nodes)
        nodes.push_back({{"id", n.id},
                         {"position", point(n.position)},
                         {"boundary", n.boundary},
                         {"n3", n.n3},
                         {"n5", n.n5},
                         {"valid", n.valid},
                         {"crossing", n.crossing}});
    return {{"curves", curves}, {"nodes", nodes}, {"absorbed", absorbed}, {"summary", summary_json(g.summary)}};
}

void add_features(json& j, const MeshStage& m) {
    const auto by = m.features.by_valence();
    json curves = json::array();
    for (const auto& pl : feature_polylines(m.tets)) {
        json pts = json::array();
        for (int v : pl.vertices) pts.push_back(point(m.tets.points.row(v).transpose()));
        curves.push_back({{"edge", pl.edge}, {"valence", m.features.valence_of(pl.edge)}, {"points", pts}});
    }
    json varying = json::array(), ambiguous = json::array();
    for (const auto& e : m.features.edges) {
        const json one = {{"edge", e.edge}, {"angle_min_deg", e.angle_min_deg}, {"angle_max_deg", e.angle_max_deg}};
        if (e.valence_varies) varying.push_back(one);
        if (ambiguous_edge(e)) ambiguous.push_back(one);
    }
    j["features"] = {{"curves", m.features.curves()},
                     {"by_valence", {{"1", by[1]}, {"2", by[2]}, {"3", by[3]}, {"4", by[4]}}},
                     {"valence_varies", varying},
                     {"ambiguous", ambiguous}};
    j["feature_curves"] = curves;
}

// The extrusions' streamlines (start, end, length, points, stop reason, used) and failures.
json extrusion_json(const Correction& c) {
    json lines = json::array(), failures = json::array();
    for (const ExtrusionStreamline& l : c.extrusion.streamlines) {
        const Points& p = l.line.points;
        json poly = json::array();
        for (Eigen::Index i = 0; i < p.rows(); ++i) poly.push_back(point(p.row(i).transpose()));
        json one = {{"source", l.source}, {"start", point(p.row(0).transpose())}, {"end", point(p.row(p.rows() - 1).transpose())},
                    {"length", l.line.length}, {"points", p.rows()}, {"stop", to_string(l.line.reason)}, {"used", l.used},
                    {"polyline", poly}};
        if (!l.used) one["failure"] = l.failure;
        lines.push_back(one);
    }
    for (const ExtrusionFailure& f : c.extrusion.failures) failures.push_back({{"what", f.what}, {"why", f.why}});
    return {{"streamlines", lines}, {"failures", failures}, {"extruded_edges", c.extrusion.edges},
            {"inserted_points", c.extrusion.points.rows()}, {"constrained_points", c.constrained_points},
            {"extrusion_seconds", c.extrusion_seconds}};
}

// Fillet: the corrected graph on the original part, and the original part solved again with it.
json mapped_json(const Correction& c) {
    if (!c.mapped) return nullptr;
    const json graph = singularities_json(*c.mapped);
    json j = {{"summary", summary_json(c.mapped->summary)}, {"moved_points", c.mapped_points},
              {"moved_nodes", c.mapped_nodes}, {"curves", graph["curves"]}, {"nodes", graph["nodes"]}};
    if (c.flat_corners) {
        const FlatCornerSolve& f = *c.flat_corners;
        j["flat_corners"] = {{"solved", f.solved}, {"runs", f.runs}, {"turned_vertices", f.turned_vertices},
                             {"summary", f.solved ? summary_json(f.graph.summary) : json(nullptr)},
                             {"curves", f.solved ? singularities_json(f.graph)["curves"] : json::array()},
                             {"seconds", f.seconds}};
    }
    return j;
}

// Method auto: every try with its result; the snap rounds of any method that snapped.
json search_json(const Correction& c) {
    json tries = json::array(), rounds = json::array();
    for (const CorrectionTry& t : c.tries)
        tries.push_back({{"method", t.method}, {"ran", t.ran}, {"kept", t.kept}, {"after", summary_json(t.after)},
                         {"rotated_fraction_10deg", t.rotated_fraction}, {"remeshed", t.remeshed},
                         {"seconds", t.seconds}, {"reason", t.reason}});
    for (const SingularitySummary& r : c.snap_rounds) rounds.push_back(summary_json(r));
    json j = {{"snap_rounds", rounds}};
    if (c.method == "auto") j.update({{"chosen", c.chosen}, {"tries", tries}, {"budget_s", c.budget_s}});
    return j;
}

// MBO's figures of one field: the report's `field`, and `correction.field_before`.
json field_json(const FrameField& f) {
    return {{"energy", f.energy}, {"initial_energy", f.initial_energy}, {"iterations", f.iterations},
            {"solver", f.solver}, {"converged", f.converged}, {"floor_iteration", f.floor_iteration},
            {"iteration_cap", f.iteration_cap}, {"extrapolations", f.extrapolations}};
}

json correction_json(const Correction& c, const SingularitySummary& after) {
    json paths = json::array();
    for (const auto& p : c.snap.paths) {
        json pts = json::array();
        for (int i = 0; i < p.points.rows(); ++i) pts.push_back(point(p.points.row(i).transpose()));
        paths.push_back({{"source_curve", p.source_curve}, {"forced", p.forced},
                         {"crosses_features", p.crosses_features}, {"points", pts}});
    }
    json fillets = json::array();
    for (const FilletOutcome& f : c.fillets) {
        json one = {{"edge", f.edge}, {"radius", f.radius}, {"done", f.done}};
        if (!f.done) one["reason"] = f.reason;
        fillets.push_back(one);
    }
    json j = {{"method", c.method},
            {"fillets", fillets},
            {"notes", c.notes},
            {"remeshed", c.remeshed},
            {"kept", c.changed && !c.worse_dropped},
            {"mapped", mapped_json(c)},
            {"fillet_seconds", c.fillet_seconds},
            {"fine_fillet_faces", c.fine_fillet_faces},
            {"remesh_seconds", c.remesh_seconds},
            {"before", summary_json(c.before)},
            {"field_before", field_json(c.field_before)},
            {"after", summary_json(after)},
            {"changed_curves", c.snap.snapped_curve_ids.size()},
            {"three_five_curves_snapped", c.snap.three_five_curves},
            {"invalid_nodes_snapped", c.snap.invalid_nodes_snapped},
            {"freed_vertices", c.snap.freed_vertices},
            {"rotated_fraction_10deg", c.rotated_fraction},
            {"seconds", c.seconds},
            {"snapped_paths", paths},
            {"curves_before", singularities_json(c.graph_before)["curves"]}};
    if (c.method.rfind("extrude", 0) == 0 || c.chosen.rfind("extrude", 0) == 0) j.update(extrusion_json(c));
    j.update(search_json(c));
    return j;
}

json blocks_json(const BlockDecomposition& b) {
    json blocks = json::array(), pairs = json::array();
    for (size_t i = 0; i < b.blocks.size(); ++i) {
        const auto& k = b.blocks[i];
        json faces = json::array();  // each cleaned face: the block across (-1: the part's boundary), its corners
        if (i < b.faces.size())
            for (size_t f = 0; f < b.faces[i].label.size(); ++f)
                faces.push_back({{"across", std::max(-1, b.faces[i].label[f])}, {"corners", b.faces[i].corners[f].size()}});
        blocks.push_back({{"face_list", faces},{"id", i},             {"tets", k.tets.size()},   {"volume", k.volume},
                          {"valid", k.valid},    {"faces", k.faces},        {"edges", k.edges},
                          {"corners", k.corners}, {"flat_edges", k.flat_edges}, {"flat_corners", k.flat_corners},
                          {"neighbours", k.neighbours}, {"centroid", point(k.centroid)}, {"reason", k.reason}});
    }
    for (const auto& p : b.neighbour_pairs)
        pairs.push_back({{"blocks", json::array({p.a, p.b})}, {"conforming", p.conforming}, {"reason", p.reason}});
    json junction_tries = json::array();
    for (const auto& t : b.junction_tries)
        junction_tries.push_back({{"mode", t.mode}, {"count", t.count}, {"valid", t.valid}, {"pairs", t.pairs},
                                  {"conforming_pairs", t.conforming_pairs}});
    return {{"count", b.count},
            {"valid", b.valid},
            {"conforming_pairs", b.conforming_pairs},
            {"pairs", b.pairs},
            {"flat_corners", b.flat_corners},
            {"flat_edges", b.flat_edges},
            {"ignored_imprints", b.ignored_imprints},
            {"boundary_wisps", b.boundary_wisps},
            {"joined_edges", b.joined_edges},
            {"glued_sources", b.glued_sources},
            {"convex_paths", b.convex_paths},
            {"curtain_corners", b.curtain_corners},
            {"ring_cuts", b.ring_cuts},
            {"ring_lenses", b.ring_lenses},
            {"rings_kept", b.rings_kept},
            {"joined_blocks", b.joined_blocks},
            {"split_blocks", b.split_blocks},
            {"prism_cuts", b.prism_cuts},
            {"carried_cuts", b.carried_cuts},
            {"triangle_folds", b.triangle_folds},
            {"junction_tries", junction_tries},
            {"junction_mode", b.junction_mode},
            {"blocks", blocks},
            {"neighbour_pairs", pairs},
            {"seconds", {{"sheets", b.seconds_sheets}, {"partition", b.seconds_partition},
                         {"validation", b.seconds_validation}, {"total", b.seconds}}}};
}

// A run whose hex mesh refined blocks adds the refined complex's figures to the blocks section:
// the same blocks as the section's own when the blocks stage kept the refinement (flat_json).
void refined_blocks_json(const HexRefinement& r, json& b) {
    b["refined"] = {{"count", r.blocks}, {"valid", r.blocks}, {"pairs", r.pairs}, {"conforming_pairs", r.pairs},
                    {"flat_edges", r.flat_edges}, {"flat_corners", r.flat_corners},
                    {"flat_edges_before", r.flat_edges_before}, {"flat_corners_before", r.flat_corners_before}};
}

json thin_json(const ThinRefinement& t) {
    return {{"tried", t.tried}, {"kept", t.kept}, {"reason", t.reason}, {"spots", t.spots}, {"faces", t.faces},
            {"min_size", t.min_size}, {"thinnest", t.thinnest}, {"without_glued", t.without_glued}, {"rounds", t.rounds}, {"tets_before", t.tets_before},
            {"tets_after", t.tets_after}, {"seconds", t.seconds},
            {"before", {{"count", t.count_before}, {"valid", t.valid_before}, {"pairs", t.pairs_before},
                        {"conforming_pairs", t.conforming_before}, {"glued_sources", t.glued_before}}},
            {"finer", {{"count", t.count_after}, {"valid", t.valid_after}, {"pairs", t.pairs_after},
                       {"conforming_pairs", t.conforming_after}}}};
}

// The blocks as the sheets cut them (`before_refinement`), and what the flat refinement did.
void flat_json(const BlockRefinement& f, json& b) {
    b["before_refinement"] = {{"count", f.count_before}, {"valid", f.valid_before}, {"pairs", f.pairs_before},
                              {"conforming_pairs", f.conforming_before}, {"flat_corners", f.flat_corners_before},
                              {"flat_edges", f.flat_edges_before}};
    b["flat_refinement"] = {{"tried", f.tried}, {"kept", f.kept}, {"reason", f.reason}, {"refined", f.refined},
                            {"seconds", f.seconds}};
}

json refinement_json(const HexRefinement& r) {
    json corners = json::array();
    for (const Eigen::Vector3d& p : r.flat_corner_positions) corners.push_back(point(p));
    return {{"applied", r.applied}, {"kept", r.kept}, {"plain_min_scaled_jacobian", r.plain_min_scaled_jacobian},
            {"refined_min_scaled_jacobian", r.refined_min_scaled_jacobian},
            {"blocks_before", r.blocks_before}, {"blocks", r.blocks}, {"refined", r.refined},
            {"pairs_before", r.pairs_before}, {"pairs", r.pairs},
            {"flat_edges_before", r.flat_edges_before}, {"flat_corners_before", r.flat_corners_before},
            {"flat_edges", r.flat_edges}, {"flat_corners", r.flat_corners}, {"skipped", r.skipped},
            {"flat_corner_positions", corners}};
}

json hexmesh_json(const HexMesh& h) {
    if (!h.done)
        return {{"done", false}, {"reason", h.reason}, {"part_volume", h.part_volume}, {"seconds", h.seconds},
                {"refinement", refinement_json(h.refinement)}};
    json blocks = json::array();
    for (size_t b = 0; b < h.blocks.size(); ++b)
        blocks.push_back({{"counts", h.blocks[b].counts}, {"hexes", h.blocks[b].hexes},
                          {"min_scaled_jacobian", h.blocks[b].min_scaled_jacobian}});
    const HexQuality& q = h.quality;
    return {{"done", true},
            {"hexes", h.hexes.size()},
            {"vertices", h.points.rows()},
            {"order", h.midpoints.empty() ? 1 : 2},
            {"size", h.size},
            {"edge_classes", h.edge_classes},
            {"off_tolerance_pairs", h.off_tolerance_pairs},
            {"refinement", refinement_json(h.refinement)},
            {"min_scaled_jacobian", q.min_scaled_jacobian},
            {"mean_scaled_jacobian", q.mean_scaled_jacobian},
            {"share_sj_ge_0_5", q.share_sj_ge_0_5},
            {"inverted", q.inverted},
            {"volume", q.volume},
            {"part_volume", h.part_volume},
            {"boundary_quads", h.boundary_quads.size()},
            {"blocks", blocks},
            {"seconds", h.seconds},
            {"hexes_per_second", h.seconds > 0 ? double(h.hexes.size()) / h.seconds : 0.0}};
}

json timings_json(const RunResult& r) {
    json t = {{"load", r.timings.load}, {"total", r.timings.total}};
    if (r.mesh) t["mesh"] = r.timings.mesh;
    if (r.field) t["field"] = r.timings.field;
    if (r.singularities) t["singularities"] = r.timings.singularities;
    if (r.correction) t["correct"] = r.timings.correct;
    if (r.blocks) t["blocks"] = r.timings.blocks;
    if (r.hexmesh) t["hexmesh"] = r.timings.hexmesh;
    return t;
}

// One entry per way the B-rep was meshed, the last one the way that worked.
json attempts_json(const std::vector<MeshAttempt>& attempts) {
    json list = json::array();
    for (const MeshAttempt& a : attempts)
        list.push_back({{"how", a.how}, {"failure", a.failure.empty() ? json(nullptr) : json(a.failure)}});
    return list;
}

}  // namespace

std::string report_json(const RunResult& r) {
    json j;
    j["version"] = 1;
    j["input"] = {{"path", r.input_path}, {"kind", r.input_kind}};
    if (r.mesh) {
        const TetMesh& m = r.mesh->tets;
        j["mesh"] = {{"vertices", m.num_vertices()}, {"tets", m.num_tets()}, {"size", m.size},
                     {"mean_edge", mean_edge_length(m, r.mesh->topology)}};
        if (!r.mesh->attempts.empty()) j["mesh"]["attempts"] = attempts_json(r.mesh->attempts);
        if (r.mesh->narrow_faces > 0) j["mesh"]["narrow_faces"] = r.mesh->narrow_faces;
        if (!r.mesh->mesher.empty()) j["mesh"]["mesher"] = r.mesh->mesher;
        add_features(j, *r.mesh);
    }
    if (r.field) {
        j["field"] = field_json(r.field->frames);
    }
    if (r.singularities) j["singularities"] = singularities_json(*r.singularities);
    if (r.correction) j["correction"] = correction_json(*r.correction, r.singularities->summary);
    if (r.blocks) j["blocks"] = blocks_json(*r.blocks);
    if (r.blocks && r.thin) j["blocks"]["thin_refinement"] = thin_json(*r.thin);
    if (r.blocks && r.flat) flat_json(*r.flat, j["blocks"]);
    if (r.hexmesh) j["hexmesh"] = hexmesh_json(*r.hexmesh);
    if (r.blocks && r.hexmesh && r.hexmesh->refinement.kept) refined_blocks_json(r.hexmesh->refinement, j["blocks"]);
    j["timings_s"] = timings_json(r);
    j["peak_memory_mb"] = r.peak_memory_mb;
    return j.dump(1);
}

}  // namespace framefix
