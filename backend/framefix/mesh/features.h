#pragma once
// Feature curves: B-rep edges (or, for imported tet meshes, boundary creases) whose dihedral
// angle theta, measured inside the solid, makes them sharp. Hex valence k = round(theta / 90 deg):
// 1 convex, 2 imprinted curve on a smooth surface, 3 concave, 4 slit. 0 means "not a feature".
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace framefix {

struct EdgeFeature {
    int edge = 0;              // B-rep edge index, 1-based (FreeCAD's Edge<i>)
    int valence = 0;           // 0 not a feature, else 1..4
    double angle_min_deg = 0;  // dihedral angle inside the solid, min over samples along the edge
    double angle_max_deg = 0;  // ... max over samples
    double length = 0;         // model units
    bool valence_varies = false;  // samples fall in more than one valence class
    std::string reason;           // for non-features: "seam", "degenerate", "tangent"
    std::vector<int> faces;       // the B-rep faces (1-based) that share the edge
    std::vector<int> vertices;    // its end vertices (1-based); one for a closed edge
};

// A dihedral angle (degrees, inside the solid) at least this far from every multiple of 90 is
// ambiguous: halfway between two hex corner types, which both fit within 22.5 degrees (a chamfer's
// 135, a wedge's 45, a gusset's 225). docs/algorithms.md#curves-along-ambiguous-edges
constexpr double kAmbiguousFromRightDeg = 22.5;

// Whether a feature edge's dihedral angle is ambiguous at every sample along it.
inline bool ambiguous_edge(const EdgeFeature& e) {
    if (e.valence <= 0) return false;
    for (double a : {e.angle_min_deg, e.angle_max_deg})
        if (std::abs(a - 90.0 * std::round(a / 90.0)) < kAmbiguousFromRightDeg) return false;
    return true;
}

struct FeatureSet {
    std::vector<EdgeFeature> edges;  // one entry per B-rep edge, edges[i].edge == i + 1

    int valence_of(int edge) const {  // 0 for unknown edges
        return edge >= 1 && edge <= int(edges.size()) ? edges[edge - 1].valence : 0;
    }
    int curves() const {
        int n = 0;
        for (const auto& e : edges) n += e.valence > 0;
        return n;
    }
    std::array<int, 5> by_valence() const {  // index k = number of features of valence k
        std::array<int, 5> n{};
        for (const auto& e : edges) n[e.valence] += 1;
        n[0] = 0;
        return n;
    }
};

}  // namespace framefix
