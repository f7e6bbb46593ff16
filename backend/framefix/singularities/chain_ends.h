#pragma once
// Internal steps of trace_chains (chains.h), one file each: chains.cpp walks the singular faces,
// chain_ends.cpp resolves where chains end and builds the nodes, curve_join.cpp joins curves
// through pass-through nodes and numbers the result.
#include <functional>
#include <vector>

#include <Eigen/Core>

#include "framefix/singularities/chains.h"
#include "framefix/core/disjoint_set.h"

namespace framefix::detail {

struct ChainContext {
    const TetMesh& mesh;
    const TetTopology& topo;
    const std::vector<int>& val;  // #F face labels 0, 3, 5, -1
    std::vector<int> ns;          // #T singular faces per tet
    std::vector<int> cluster;     // #T junction cluster id, -1 for tets that are not node tets
    int nclusters = 0;
};

enum class EndType { Junction, Boundary, Dead };

struct RawEnd {
    EndType type = EndType::Dead;
    int face = -1;   // last singular face of the chain on this side
    int tet = -1;    // tet beyond that face, -1 on the boundary
    int group = -1;  // junction cluster / dead-end group / boundary group once resolved
};

struct RawChain {
    std::vector<int> faces;  // chain order
    bool closed = false;
    RawEnd ends[2];          // unused when closed
};

Eigen::Vector3d face_centroid(const TetMesh& mesh, const TetTopology& topo, int f);
// Groups of the points closer than `radius` to another of their group (single linkage): one
// group id per point. For the few dead ends of a graph, so the quadratic pass is fine.
std::vector<int> close_groups(const std::vector<Eigen::Vector3d>& points, double radius);

ChainContext classify_tets(const TetMesh& mesh, const TetTopology& topo, const std::vector<int>& val);
// Leave face f through `side`: true with the next face and the side it is entered from, or false
// with the end reached.
bool step(const ChainContext& c, int f, int side, int* next, int* next_side, RawEnd* end);
std::vector<RawChain> walk_chains(const ChainContext& c);

struct EndStats {
    int dead_ends = 0, attached = 0;
};
// Dead ends -> junction / boundary / dead-end groups; boundary ends -> boundary groups.
EndStats resolve_ends(const ChainContext& c, double attach_radius, std::vector<RawChain>& chains);
// Drops junk chains, creates one node per referenced group and the raw polylines.
void assemble(const ChainContext& c, const std::vector<RawChain>& chains, ChainGraph& graph);
int join_pass_through(ChainGraph& graph);
// Joins pass-through nodes and drops the loops at a junction that stay within about 2 edge
// lengths of its tets (docs/algorithms.md#chain-ends-and-nodes), until neither changes the graph;
// returns how many nodes were joined. The loops are judged on the joined curves, so that a corner
// of the field that splits a loop does not save it.
int join_and_drop_loops(ChainGraph& graph, const TetMesh& mesh);
void renumber(ChainGraph& graph);

// Whether a crossing is joined: `after` is `before` with curves a and b split at the new interior
// node `node`; the pieces are a, b and the curves appended after before's.
using CrossingCheck =
    std::function<bool(const ChainGraph& before, const ChainGraph& after, int a, int b, int node)>;
// A curve that passes within about one edge length of the inside of another curve and then leaves
// through the boundary within about three has crossed it at a node the chains missed: both are
// split there, at a new interior node, where `accept` agrees
// (docs/algorithms.md#crossings-near-the-boundary). Returns how many such nodes were added.
int join_crossings(ChainGraph& graph, const TetTopology& topo, const CrossingCheck& accept);

}  // namespace framefix::detail
