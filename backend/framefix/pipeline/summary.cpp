// The one-line summary the CLI prints after a run.
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "framefix/pipeline/report.h"

namespace framefix {

std::string human_summary(const RunResult& r) {
    const Correction* correction = r.correction ? &*r.correction : nullptr;
    const BlockDecomposition* blocks = r.blocks ? &*r.blocks : nullptr;
    const std::string name = std::filesystem::path(r.input_path.empty() ? "shape" : r.input_path).filename();
    char tets[32];
    const int nt = r.mesh ? r.mesh->tets.num_tets() : 0;
    if (nt >= 10000) std::snprintf(tets, sizeof tets, "%dk tets", int(std::lround(nt / 1000.0)));
    else std::snprintf(tets, sizeof tets, "%d tets", nt);
    std::string s = name + ": " + tets;
    if (r.singularities) {
        const auto& m = r.singularities->summary;
        s += ", " + std::to_string(m.curves) + " singular curve" + (m.curves == 1 ? "" : "s");
        if (m.curves > 0) {
            s += ": ";
            std::vector<std::string> parts;
            if (m.curves_3_5) parts.push_back(std::to_string(m.curves_3_5) + " 3-5");
            if (m.valence3) parts.push_back(std::to_string(m.valence3) + " valence-3");
            if (m.valence5) parts.push_back(std::to_string(m.valence5) + " valence-5");
            const int other = m.curves - m.curves_3_5 - m.valence3 - m.valence5;  // kind Other: no valence read
            if (other > 0) parts.push_back(std::to_string(other) + " other");
            for (size_t i = 0; i < parts.size(); ++i) s += (i ? ", " : "") + parts[i];
        }
        if (m.invalid_nodes) s += ", " + std::to_string(m.invalid_nodes) + " invalid node" + (m.invalid_nodes == 1 ? "" : "s");
        s += m.meshable ? " (hex-meshable)" : " (not hex-meshable)";
    } else if (r.mesh) {
        s += ", " + std::to_string(r.mesh->features.curves()) + " feature curves";
    }
    if (correction) {
        const auto& b = correction->before;
        s += "; before " + correction->method + ": " + std::to_string(b.curves_3_5) + " 3-5 curve" +
             (b.curves_3_5 == 1 ? "" : "s") + ", ";
        if (correction->method == "fillet") {
            int done = 0;
            for (const FilletOutcome& f : correction->fillets) done += f.done;
            s += std::to_string(done) + " of " + std::to_string(correction->fillets.size()) + " edge" +
                 (correction->fillets.size() == 1 ? "" : "s") + " filleted";
        } else {
            s += std::to_string(correction->snap.snapped_curve_ids.size()) + " snapped";
        }
    }
    if (blocks) {
        s += "; " + std::to_string(blocks->count) + " block" + (blocks->count == 1 ? "" : "s") + ", " +
             (blocks->valid == blocks->count ? std::string("all valid") : std::to_string(blocks->valid) + " valid") +
             ", " + std::to_string(blocks->conforming_pairs) + "/" + std::to_string(blocks->pairs) + " pairs conforming";
        if (blocks->flat_edges) s += ", " + std::to_string(blocks->flat_edges) + " flat edge" + (blocks->flat_edges == 1 ? "" : "s");
        if (r.flat && r.flat->kept)
            s += " (" + std::to_string(r.flat->refined) + " block" + (r.flat->refined == 1 ? "" : "s") +
                 " with a flat edge split in three, from " + std::to_string(r.flat->count_before) + ")";
        if (r.thin && r.thin->kept)
            s += " (meshed again finer next to " + std::to_string(r.thin->faces) + " face" + (r.thin->faces == 1 ? "" : "s") +
                 (r.thin->rounds > 1 ? ", then again" : "") + ": blocks thinner than 3 h)";
    }
    if (const auto& hex = r.hexmesh) {
        char q[96];
        std::snprintf(q, sizeof q, "; %zu hex%s, min scaled Jacobian %.2f, %d inverted", hex->hexes.size(),
                      hex->hexes.size() == 1 ? "" : "es", hex->quality.min_scaled_jacobian, hex->quality.inverted);
        s += hex->done ? std::string(q) : "; no hex mesh: " + hex->reason;
        const HexRefinement& ref = hex->refinement;
        if (hex->done && ref.kept && !(r.flat && r.flat->kept))
            s += " (" + std::to_string(ref.refined) + " block" + (ref.refined == 1 ? "" : "s") + " with a flat edge split in three)";
    }
    if (r.mesh && r.mesh->attempts.size() > 1)
        s += "; meshed on try " + std::to_string(r.mesh->attempts.size()) + " (" + r.mesh->attempts.back().how +
             ") after: " + r.mesh->attempts.front().failure;
    char t[32];
    std::snprintf(t, sizeof t, "; %.1f s", r.timings.total);
    return s + t;
}

}  // namespace framefix
