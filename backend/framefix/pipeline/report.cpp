#include "framefix/pipeline/report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "framefix/core/error.h"

namespace framefix {
namespace {

using json = nlohmann::json;

json point(const Eigen::Vector3d& p) { return json::array({p.x(), p.y(), p.z()}); }

json summary_json(const SingularitySummary& s) {
    return {{"curves", s.curves},         {"valence3", s.valence3}, {"valence5", s.valence5},
            {"curves_3_5", s.curves_3_5}, {"nodes", s.nodes},       {"invalid_nodes", s.invalid_nodes},
            {"meshable", s.meshable}};
}

json singularities_json(const SingularityGraph& g) {
    json curves = json::array(), nodes = json::array();
    for (const auto& c : g.curves) {
        json pts = json::array();
        for (int i = 0; i < c.points.rows(); ++i) pts.push_back(point(c.points.row(i).transpose()));
        curves.push_back({{"id", c.id},
                          {"kind", to_string(c.kind)},
                          {"length", c.length},
                          {"ends", json::array({c.ends[0], c.ends[1]})},
                          {"closed", c.closed},
                          {"end_valences", json::array({c.end_valence[0], c.end_valence[1]})},
                          {"triangles", c.faces.size()},
                          {"transition", c.transition},
                          {"stable_direction", point(c.stable_direction)},
                          {"points", pts}});
    }
    for (const auto& n : g.nodes)
        nodes.push_back({{"id", n.id},
                         {"position", point(n.position)},
                         {"boundary", n.boundary},
                         {"n3", n.n3},
                         {"n5", n.n5},
                         {"valid", n.valid}});
    return {{"curves", curves}, {"nodes", nodes}, {"summary", summary_json(g.summary)}};
}

void add_features(json& j, const AnalysisResult& r) {
    const auto by = r.features.by_valence();
    json curves = json::array();
    for (const auto& pl : feature_polylines(r.mesh)) {
        json pts = json::array();
        for (int v : pl.vertices) pts.push_back(point(r.mesh.points.row(v).transpose()));
        curves.push_back({{"edge", pl.edge}, {"valence", r.features.valence_of(pl.edge)}, {"points", pts}});
    }
    json varying = json::array();
    for (const auto& e : r.features.edges)
        if (e.valence_varies)
            varying.push_back({{"edge", e.edge}, {"angle_min_deg", e.angle_min_deg}, {"angle_max_deg", e.angle_max_deg}});
    j["features"] = {{"curves", r.features.curves()},
                     {"by_valence", {{"1", by[1]}, {"2", by[2]}, {"3", by[3]}, {"4", by[4]}}},
                     {"valence_varies", varying}};
    j["feature_curves"] = curves;
}

json correction_json(const Correction& c, const SingularitySummary& after) {
    json paths = json::array();
    for (const auto& p : c.snap.paths) {
        json pts = json::array();
        for (int i = 0; i < p.points.rows(); ++i) pts.push_back(point(p.points.row(i).transpose()));
        paths.push_back({{"source_curve", p.source_curve}, {"forced", p.forced},
                         {"crosses_features", p.crosses_features}, {"points", pts}});
    }
    return {{"method", c.method},
            {"before", summary_json(c.before)},
            {"after", summary_json(after)},
            {"changed_curves", c.snap.snapped_curve_ids.size()},
            {"three_five_curves_snapped", c.snap.three_five_curves},
            {"freed_vertices", c.snap.freed_vertices},
            {"rotated_fraction_10deg", c.rotated_fraction},
            {"seconds", c.seconds},
            {"snapped_paths", paths},
            {"curves_before", singularities_json(c.graph_before)["curves"]}};
}

json blocks_json(const BlockDecomposition& b) {
    json blocks = json::array(), pairs = json::array();
    for (size_t i = 0; i < b.blocks.size(); ++i) {
        const auto& k = b.blocks[i];
        blocks.push_back({{"id", i},             {"tets", k.tets.size()},   {"volume", k.volume},
                          {"valid", k.valid},    {"faces", k.faces},        {"edges", k.edges},
                          {"corners", k.corners}, {"flat_edges", k.flat_edges}, {"flat_corners", k.flat_corners},
                          {"neighbours", k.neighbours}, {"centroid", point(k.centroid)}, {"reason", k.reason}});
    }
    for (const auto& p : b.neighbour_pairs)
        pairs.push_back({{"blocks", json::array({p.a, p.b})}, {"conforming", p.conforming}, {"reason", p.reason}});
    return {{"count", b.count},
            {"valid", b.valid},
            {"conforming_pairs", b.conforming_pairs},
            {"pairs", b.pairs},
            {"flat_corners", b.flat_corners},
            {"flat_edges", b.flat_edges},
            {"blocks", blocks},
            {"neighbour_pairs", pairs},
            {"seconds", {{"sheets", b.seconds_sheets}, {"partition", b.seconds_partition},
                         {"validation", b.seconds_validation}, {"total", b.seconds}}}};
}

}  // namespace

std::string report_json(const AnalysisResult& r, const Correction* correction, const BlockDecomposition* blocks) {
    json j;
    j["version"] = 1;
    j["input"] = {{"path", r.input_path}, {"kind", r.input_kind}};
    j["mesh"] = {{"vertices", r.mesh.num_vertices()}, {"tets", r.mesh.num_tets()}, {"size", r.mesh.size}};
    add_features(j, r);
    if (r.has_field)
        j["field"] = {{"energy", r.field.energy},
                      {"initial_energy", r.field.initial_energy},
                      {"iterations", r.field.iterations},
                      {"solver", r.field.solver}};
    if (r.has_singularities) j["singularities"] = singularities_json(r.singularities);
    if (correction) j["correction"] = correction_json(*correction, r.singularities.summary);
    if (blocks) j["blocks"] = blocks_json(*blocks);
    json t = {{"load", r.timings.load}, {"mesh", r.timings.mesh}, {"total", r.timings.total}};
    if (r.has_field) t["field"] = r.timings.field;
    if (r.has_singularities) t["singularities"] = r.timings.singularities;
    if (correction) t["correct"] = correction->seconds;
    if (blocks) t["blocks"] = blocks->seconds;
    j["timings_s"] = t;
    j["peak_memory_mb"] = r.peak_memory_mb;
    return j.dump(1);
}

std::string human_summary(const AnalysisResult& r, const Correction* correction, const BlockDecomposition* blocks) {
    const std::string name = std::filesystem::path(r.input_path.empty() ? "shape" : r.input_path).filename();
    char tets[32];
    const int nt = r.mesh.num_tets();
    if (nt >= 10000) std::snprintf(tets, sizeof tets, "%dk tets", int(std::lround(nt / 1000.0)));
    else std::snprintf(tets, sizeof tets, "%d tets", nt);
    std::string s = name + ": " + tets;
    if (r.has_singularities) {
        const auto& m = r.singularities.summary;
        s += ", " + std::to_string(m.curves) + " singular curve" + (m.curves == 1 ? "" : "s");
        if (m.curves > 0) {
            s += ": ";
            std::vector<std::string> parts;
            if (m.curves_3_5) parts.push_back(std::to_string(m.curves_3_5) + " 3-5");
            if (m.valence3) parts.push_back(std::to_string(m.valence3) + " valence-3");
            if (m.valence5) parts.push_back(std::to_string(m.valence5) + " valence-5");
            for (size_t i = 0; i < parts.size(); ++i) s += (i ? ", " : "") + parts[i];
        }
        if (m.invalid_nodes) s += ", " + std::to_string(m.invalid_nodes) + " invalid node" + (m.invalid_nodes == 1 ? "" : "s");
        s += m.meshable ? " (hex-meshable)" : " (not hex-meshable)";
    } else {
        s += ", " + std::to_string(r.features.curves()) + " feature curves";
    }
    if (correction) {
        const auto& b = correction->before;
        s += "; before " + correction->method + ": " + std::to_string(b.curves_3_5) + " 3-5 curve" +
             (b.curves_3_5 == 1 ? "" : "s") + ", " + std::to_string(correction->snap.snapped_curve_ids.size()) + " snapped";
    }
    if (blocks) {
        s += "; " + std::to_string(blocks->count) + " block" + (blocks->count == 1 ? "" : "s") + ", " +
             (blocks->valid == blocks->count ? std::string("all valid") : std::to_string(blocks->valid) + " valid") +
             ", " + std::to_string(blocks->conforming_pairs) + "/" + std::to_string(blocks->pairs) + " pairs conforming";
        if (blocks->flat_edges) s += ", " + std::to_string(blocks->flat_edges) + " flat edge" + (blocks->flat_edges == 1 ? "" : "s");
    }
    char t[32];
    std::snprintf(t, sizeof t, "; %.1f s", r.timings.total + (blocks ? blocks->seconds : 0.0));
    return s + t;
}

}  // namespace framefix
