// Curve extremities: node kinds, dead ends merged into junctions, junk chains.
#include <limits>
#include <string>

#include "framefix/core/error.h"
#include "framefix/corrections/snap_plan.h"

namespace framefix {

namespace {

// Number of open-curve ends at each node (a curve with both ends at one node counts twice).
std::vector<int> node_degrees(const SingularityGraph& graph) {
    std::vector<int> degree(graph.nodes.size(), 0);
    for (const SingularCurve& c : graph.curves) {
        if (c.closed) continue;
        for (int k = 0; k < 2; ++k) {
            if (c.ends[k] < 0 || c.ends[k] >= int(graph.nodes.size()))
                throw Error("snap", "open singular curve " + std::to_string(c.id) + " has end node " +
                                        std::to_string(c.ends[k]) + " outside the graph's " +
                                        std::to_string(graph.nodes.size()) + " nodes");
            ++degree[c.ends[k]];
        }
    }
    return degree;
}

bool all_complex(const SingularityGraph& graph, const SingularCurve& c) {
    for (int face : c.faces) {
        const bool known = face >= 0 && face < int(graph.face_valence.size());
        if (!known || graph.face_valence[face] != -1) return false;
    }
    return !c.faces.empty();
}

}  // namespace

CurveEnds classify_curve_ends(const SingularityGraph& graph, double dead_end_radius) {
    const int n_nodes = int(graph.nodes.size());
    const std::vector<int> degree = node_degrees(graph);
    CurveEnds ends;
    ends.node_rep.resize(n_nodes);
    ends.node_kind.resize(n_nodes);
    for (int n = 0; n < n_nodes; ++n) {
        ends.node_rep[n] = n;
        // A node with junction tets, or where several curves meet, is an interior node; a lone
        // end without tets is a dead end (the extractor keeps those it could not attach).
        const SingularNode& node = graph.nodes[n];
        ends.node_kind[n] = node.boundary                             ? EndKind::Boundary
                            : !node.tets.empty() || degree[n] >= 2 ? EndKind::Junction
                                                                   : EndKind::DeadEnd;
    }
    // Ring curves often stop one tet short of their junction: such a dead end is that junction.
    for (int n = 0; n < n_nodes; ++n) {
        if (ends.node_kind[n] != EndKind::DeadEnd) continue;
        int best = -1;
        double best_d = std::numeric_limits<double>::infinity();
        for (int j = 0; j < n_nodes; ++j) {
            if (ends.node_kind[j] != EndKind::Junction) continue;
            const double d = (graph.nodes[j].position - graph.nodes[n].position).norm();
            if (d < best_d) best_d = d, best = j;
        }
        if (best >= 0 && best_d < dead_end_radius) {
            ends.node_rep[n] = best;
            ends.node_kind[n] = EndKind::Junction;
        }
    }
    ends.excluded.assign(graph.curves.size(), 0);
    for (size_t i = 0; i < graph.curves.size(); ++i) {
        const SingularCurve& c = graph.curves[i];
        if (c.closed) {
            ends.excluded[i] = 1;
            continue;
        }
        // Tiny chains at one junction, or made of 120/180 deg faces only, are pieces of the node.
        const bool same_junction = ends.node_rep[c.ends[0]] == ends.node_rep[c.ends[1]] &&
                                   ends.node_kind[c.ends[0]] == EndKind::Junction;
        ends.excluded[i] = c.faces.size() <= 2 && (same_junction || all_complex(graph, c));
    }
    return ends;
}

}  // namespace framefix
