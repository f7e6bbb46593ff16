#include "framefix/pipeline/correction_methods.h"

#include "framefix/core/error.h"

namespace framefix {
namespace {

// Boundary snapping: the ends of each 3-5 curve are pulled onto the boundary and the frames
// along the boundary path between them are set so that the curve lies on the boundary.
bool apply_snap(CorrectionContext& c) {
    c.record.snap = snap_three_five_curves(c.mesh.tets, c.mesh.topology, c.mesh.features, c.field.constraints,
                                           c.field.frames, c.graph, c.options.snap);
    if (c.record.snap.snapped_curve_ids.empty()) return false;
    c.field.constraints = c.record.snap.constraints;
    return true;
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
        {"snap", "snap 3-5 curves onto the boundary (the paper's recommendation)", true, &apply_snap},
        {"fillet", "insert fillets on the B-rep along the concave feature curves that cause 3-5 curves", false, nullptr},
        {"extrude-curves", "extrude the concave feature curves into the volume along the field's stable direction", false, nullptr},
        {"extrude-nodes", "extrude the boundary singular nodes into the volume along streamlines of the field", false, nullptr},
    };
    return methods;
}

const CorrectionMethod& find_correction_method(const std::string& name) {
    for (const auto& m : correction_methods()) {
        if (m.name != name) continue;
        if (!m.available)
            throw Error("correct", "method '" + name + "' is not available yet; use --method " + correction_methods()[0].name +
                                       " (the paper's recommendation)");
        return m;
    }
    throw Error("correct", "unknown method '" + name + "'; use " + names());
}

}  // namespace framefix
